#!/bin/bash
# Session 16: after the seam, content, textures, d3d11api, sm1 and language branches
# (xlate in concept folders, ParsedSpirv, 3D and multisampled textures, skinned models, D3D10 spellings, live SM1-3 constants):
# every GPU test binary bundled from tests/runtime and tests/d3d11 on the H100/H200 (EGL), vkd3d's HLSL suite there, and the two demos' final images.
# Bundle: .devbundle-s16g/t.tar.xz = {bin/,lib/,content/} of main at the measured commit
# (scripts/make-device-bundle build-dev <all those test binaries> tests/conformance/shader_test_runner
#  demo/fxdemo, binaries stripped, plus build-dev/content), the suite's files in .vkd3d-suite/.
# Run (device tool, carry .gl .devbundle-s16g .vkd3d-suite): bash docs/report/device-runs/session16.sh
BUNDLE=.devbundle-s16g exec bash docs/report/device-runs/gpu-tests.sh
