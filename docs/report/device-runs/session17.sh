#!/bin/bash
# Session 17: after D3D9 pixel centres moved into the viewport's origin (glViewportIndexedf: exactly half a
# pixel across, half minus 1/256 down) and objects in cbuffers moved out before glslang: the bundled GPU test
# binaries (tests/runtime, tests/d3d11, the render references' render_deferred_test) on the H100/H200 (EGL),
# vkd3d's HLSL suite there, and the two demos' final images.
# Bundle: .devbundle-s17g/t.tar.xz = {bin/,lib/,content/} of main at the measured commit
# (scripts/make-device-bundle build-dev <the test binaries> tests/conformance/shader_test_runner demo/fxdemo,
#  binaries stripped, plus build-dev/content), the suite's files in .vkd3d-suite/.
# Run (device tool, carry .gl .devbundle-s17g .vkd3d-suite): bash docs/report/device-runs/session17.sh
BUNDLE=.devbundle-s17g exec bash docs/report/device-runs/gpu-tests.sh
