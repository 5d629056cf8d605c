#!/bin/bash
# Session 22: after read-only depth-stencil views, the Texture1D refusal at draws and DX9 1D sampling on
# one-row textures (and the BC1 tolerance of session 21): the bundled GPU test binaries (d3d11_test,
# tests/runtime one-row textures, HLSL shapes, texture filtering, stock effects, pass sampler stages,
# render_deferred_test) on the H200 (EGL), vkd3d's HLSL suite there, and the two demos' final images.
# Bundle: .devbundle-s22/t.tar.xz = {bin/,lib/,content/} of main at the measured commit.
# Run (device tool, carry .gl .devbundle-s22 .vkd3d-suite): bash docs/report/device-runs/session22.sh
BUNDLE=.devbundle-s22 exec bash docs/report/device-runs/gpu-tests.sh
