#!/bin/bash
# Session 24: after gathers with four offsets as four gathers, VS/DS-written SV_RenderTargetArrayIndex
# and SV_ViewportArrayIndex (gl_Layer / gl_ViewportIndex behind their extensions), SV_VertexID less the
# draw's start vertex, XNA hardware instancing (SetVertexBuffers, DrawInstancedPrimitives), Effect.Clone,
# the DXGI factory/adapter/output calls and the xlate fixes of runs 24/25: the bundled GPU test binaries
# (d3d11_test, tests/runtime HLSL shapes/accepted forms/instancing/clone/stock effects/sixth-wave render,
# render_deferred_test) on the GPU (EGL), vkd3d's HLSL suite there, and the two demos' final images.
# Bundle: .devbundle-s24/t.tar.xz = {bin/,lib/,content/} of main at the measured commit.
# Run (device tool, carry .gl .devbundle-s24 .vkd3d-suite): bash docs/report/device-runs/session24.sh
BUNDLE=.devbundle-s24 exec bash docs/report/device-runs/gpu-tests.sh
