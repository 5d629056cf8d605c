# fxdemo rastertek50: Rastertek DirectX 10 tutorial 50 "Deferred Shading" (seed 004) on fxport.
list(APPEND FXDEMO_SOURCES
  rastertek50/applicationclass.cpp
  rastertek50/cameraclass.cpp
  rastertek50/d3dclass.cpp
  rastertek50/d3dx_math.cpp
  rastertek50/deferredbuffersclass.cpp
  rastertek50/deferredshaderclass.cpp
  rastertek50/inputclass.cpp
  rastertek50/lightclass.cpp
  rastertek50/lightshaderclass.cpp
  rastertek50/modelclass.cpp
  rastertek50/orthowindowclass.cpp
  rastertek50/readback.cpp
  rastertek50/reference_check.cpp
  rastertek50/run_rastertek50.cpp
  rastertek50/textureclass.cpp)
