#!/bin/bash
# Session 23: after POSITIONn as a user varying at SM4+, SV_InstanceID from 0, the program cache keyed by
# varyings, ID3D11Texture1D over GL 1D textures, XNA's TextureFormat (DXT kept/compressed), textures at
# t32..t127, and the xlate fixes (matrix operators in bracket groups, static initializers calling
# functions, arrays of arrays, local resource variables, struct <-> array conversions, flat lists): the
# bundled GPU test binaries (d3d11_test, tests/runtime HLSL shapes/accepted forms/struct parameters/DXT
# formats/stock effects, render_deferred_test; three binaries left out to fit the 64 MiB carry) on
# the GPU (EGL), vkd3d's HLSL suite there, and the two demos' final images.
# Bundle: .devbundle-s23/t.tar.xz = {bin/,lib/,content/} of main at the measured commit.
# Run (device tool, carry .gl .devbundle-s23 .vkd3d-suite): bash docs/report/device-runs/session23.sh
BUNDLE=.devbundle-s23 exec bash docs/report/device-runs/gpu-tests.sh
