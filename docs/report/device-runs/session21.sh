#!/bin/bash
# Session 21: after stream output (GL transform feedback behind the backend seam) and block-compressed
# and packed-float formats stored natively (session 20): the bundled GPU test binaries (tests/runtime,
# tests/d3d11 with the stream-output, compressed-format and multisample tests, render_deferred_test) on
# the H200 (EGL), vkd3d's HLSL suite there, and the two demos' final images.
# Bundle: .devbundle-s21/t.tar.xz = {bin/,lib/,content/} of main at the measured commit.
# Run (device tool, carry .gl .devbundle-s21 .vkd3d-suite): bash docs/report/device-runs/session21.sh
BUNDLE=.devbundle-s21 exec bash docs/report/device-runs/gpu-tests.sh
