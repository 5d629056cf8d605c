# Tests of the deferred demo (issue 6 part 3): what Game1 builds for a scene (effects, targets,
# passes) and frustum culling, asserted on Game1 itself (deferred/build_report.h), plus --explain
# from the command line. Included by demo/CMakeLists.txt when FXPORT_BUILD_TESTS is on.
find_package(GTest CONFIG REQUIRED)  # demo/ is configured before tests/, which finds it too
include(GoogleTest)
file(GLOB FXDEMO_DEFERRED_TEST_SOURCES CONFIGURE_DEPENDS
  ${CMAKE_CURRENT_SOURCE_DIR}/common/*.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/deferred/*.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/deferred/Cameras/*.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/deferred/Lights/*.cpp)
# run_deferred and the debug sheet are fxdemo's (frame loop, PNGs); the test drives Game1 itself.
list(FILTER FXDEMO_DEFERRED_TEST_SOURCES EXCLUDE REGEX "/deferred/(run_deferred|debug_sheet)\\.cpp$")
add_executable(deferred_scene_test deferred/tests/scene_resources_test.cpp ${FXDEMO_DEFERRED_TEST_SOURCES})
# The seed's headers name setter parameters like their fields (see demo/CMakeLists.txt).
set_source_files_properties(deferred/tests/scene_resources_test.cpp PROPERTIES COMPILE_OPTIONS -Wno-shadow)
target_include_directories(deferred_scene_test PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
target_compile_definitions(deferred_scene_test PRIVATE
  FXPORT_HLSL_DIR="${PROJECT_SOURCE_DIR}/hlsl"
  FXPORT_CONTENT_DIR="${CMAKE_BINARY_DIR}/content")
target_link_libraries(deferred_scene_test PRIVATE fxport_framework fxport_graphics fxport_platform fxport_warnings GTest::gtest_main)
set_source_files_properties(${FXDEMO_DEFERRED_TEST_SOURCES} PROPERTIES COMPILE_OPTIONS -Wno-shadow)
if(TARGET content)
  add_dependencies(deferred_scene_test content)
endif()
gtest_discover_tests(deferred_scene_test TEST_PREFIX "demo.deferred." DISCOVERY_TIMEOUT 60
                     PROPERTIES ENVIRONMENT "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/tests/support/lsan.supp")

# --explain from the command line: a directional-light-only scene without SSAO lists the spot light's
# effect and shadow map as left out.
add_test(NAME demo.deferred.explain_directional_only
         COMMAND fxdemo deferred --size 160x96 --frames 1 --lights d --no-ssao --explain
                 --out ${CMAKE_BINARY_DIR}/test-out/deferred-explain)
set_tests_properties(demo.deferred.explain_directional_only PROPERTIES
  PASS_REGULAR_EXPRESSION "left out  Effects/SpotLight.*left out  SpotLight\\.shadowMap.*passes left out: ShadowMaps"
  FAIL_REGULAR_EXPRESSION "built     Effects/(SpotLight|PointLight|DepthWriter|SSAO)")
list(APPEND FXDEMO_TESTS demo.deferred.explain_directional_only)
