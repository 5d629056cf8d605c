#!/bin/bash
# Session 25: after the D3D11 front end's viewport arrays (RSSetViewports / RSSetScissorRects with several
# entries, GS/VS SV_ViewportArrayIndex), B8G8R8X8 and D32_FLOAT_S8X24_UINT, typeless colour/BC textures
# through texture views, cube arrays, 1D render-target/depth views and stream-output queries; the xlate
# fixes of the conformance and rw26 helpers (write-only typed UAVs without a format, ROVs through fragment
# shader interlock, index-before-base evaluation, struct member functions, cbuffer slot counting): the
# bundled GPU test binaries, vkd3d's HLSL suite on the GPU, and the two demos' final images.
# Bundle: .devbundle-s25/t.tar.xz = {bin/,lib/,content/} of main at the measured commit.
# Run (device tool, carry .gl .devbundle-s25 .vkd3d-suite): bash docs/report/device-runs/session25.sh
BUNDLE=.devbundle-s25 exec bash docs/report/device-runs/gpu-tests.sh
