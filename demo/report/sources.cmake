# fxdemo report (issue 6, part 1): error against GPU time for each demo's quality knobs.
list(APPEND FXDEMO_SOURCES
  report/deferred_sweep.cpp
  report/lighting2d_reference.cpp
  report/lighting2d_sweep.cpp
  report/measurement.cpp
  report/pointlights_sweep.cpp
  report/rastertek50_sweep.cpp
  report/report_files.cpp
  report/report_plot.cpp
  report/run_report.cpp
  report/sweep.cpp)
