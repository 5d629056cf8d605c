#!/bin/bash
# Session 18: after texture arrays (device core + D3D11 front end), per-sample input evaluation, packed
# geometry-shader clip/cull inputs and ByteAddressBuffer sizes in bytes: the bundled GPU test binaries
# (tests/runtime, tests/d3d11 with the new texture-array tests, render_deferred_test) on the H200 (EGL),
# vkd3d's HLSL suite there, and the two demos' final images.
# Bundle: .devbundle-s18g/t.tar.xz = {bin/,lib/,content/} of main at the measured commit (as session 17's).
# Run (device tool, carry .gl .devbundle-s18g .vkd3d-suite): bash docs/report/device-runs/session18.sh
BUNDLE=.devbundle-s18g exec bash docs/report/device-runs/gpu-tests.sh
