# raygate_add_test(NAME <name> LABEL unit|integration SOURCES ... [LIBS ...] [TIMEOUT s] [SERIAL])
# One GoogleTest executable; its tests are registered with CTest individually and labelled,
# so `ctest -L unit` runs the fast ones.
include(GoogleTest)

function(raygate_add_test)
  cmake_parse_arguments(T "SERIAL" "NAME;LABEL;TIMEOUT" "SOURCES;LIBS" ${ARGN})
  if(NOT T_LABEL MATCHES "^(unit|integration)$")
    message(FATAL_ERROR "raygate_add_test(${T_NAME}): LABEL must be unit or integration")
  endif()
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 120)
  endif()
  # Under AddressSanitizer and UBSan (the asan preset, Debug) a test runs 3-10 times slower; on a
  # busy 2-core runner the simulation tests then outlived their 120 s (2026-11-28). The limit
  # guards against a hang, not a slow build, so sanitizer builds give every test 5 times as long.
  set(time_scale 1)
  if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=")
    set(time_scale 5)
    math(EXPR T_TIMEOUT "${T_TIMEOUT} * ${time_scale}")
  endif()
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main GTest::gmock
                        raygate_warnings)
  if(time_scale GREATER 1)
    # The same factor for the time limits tests set on the runs they start (cli/cli_support.h).
    target_compile_definitions(${T_NAME} PRIVATE RAYGATE_TEST_TIME_SCALE=${time_scale})
  endif()
  target_compile_definitions(${T_NAME} PRIVATE
    RAYGATE_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    RAYGATE_BINARY_DIR="${PROJECT_BINARY_DIR}"
    RAYGATE_SHARED_DIR="${PROJECT_SOURCE_DIR}/../shared")
  # SERIAL: the test judges real timings, so no other test may share the CPUs with it.
  set(serial FALSE)
  if(T_SERIAL)
    set(serial TRUE)
  endif()
  gtest_discover_tests(${T_NAME} PROPERTIES LABELS ${T_LABEL} TIMEOUT ${T_TIMEOUT}
                       RUN_SERIAL ${serial} DISCOVERY_TIMEOUT 60)
endfunction()
