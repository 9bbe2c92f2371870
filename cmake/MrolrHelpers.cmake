# Helper functions shared by every target of MROLR: the same standard, warnings and sanitizers
# everywhere, so a target never forgets them.

# Options common to every MROLR target.
function(mrolr_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_17)
  set_target_properties(${target} PROPERTIES CXX_EXTENSIONS OFF)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow)
  target_compile_definitions(${target} PRIVATE MROLR_SOURCE_DIR="${MROLR_SOURCE_DIR}")
  if(MROLR_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# mrolr_add_library(<area> SOURCES a.cpp ... [DEPENDS targets...])
# Creates the static library mrolr_<area> with alias mrolr::<area>. The public include directory is
# libmrolr/include, so headers are included as <mrolr/<area>/X.h>.
function(mrolr_add_library area)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  set(target mrolr_${area})
  add_library(${target} STATIC ${ARG_SOURCES})
  add_library(mrolr::${area} ALIAS ${target})
  target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR}/libmrolr/include)
  target_link_libraries(${target} PUBLIC ${ARG_DEPENDS})
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  mrolr_target_defaults(${target})
endfunction()

# mrolr_add_app(<name> SOURCES main.cpp [DEPENDS targets...]) -> build/bin/<name>
function(mrolr_add_app name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS})
  mrolr_target_defaults(${name})
endfunction()

# mrolr_add_test(<name> SOURCES x_test.cpp [DEPENDS targets...] [LABELS l...])
# One GoogleTest binary; every TEST in it becomes a ctest test.
function(mrolr_add_test name)
  cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;DEPENDS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} GTest::gtest GTest::gtest_main)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  mrolr_target_defaults(${name})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  if(MROLR_SANITIZE)
    # the timeouts catch hangs; sanitized code runs about 10x slower (the rendered-scene
    # evaluation: 62 s plain, over 600 s with ASan/UBSan)
    math(EXPR ARG_TIMEOUT "${ARG_TIMEOUT} * 4")
  endif()
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  gtest_discover_tests(${name}
    TEST_PREFIX "${name}."
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT ${ARG_TIMEOUT}
    DISCOVERY_TIMEOUT 60)
endfunction()

# mrolr_add_bench(<name> SOURCES x_bench.cpp [DEPENDS targets...]) -> build/bench/bin/<name>
function(mrolr_add_bench name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} benchmark::benchmark)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bench/bin)
  mrolr_target_defaults(${name})
endfunction()

# Adds every immediate subfolder of <dir> that has a CMakeLists.txt, in sorted order.
function(mrolr_add_subdirectories dir)
  file(GLOB children RELATIVE ${CMAKE_CURRENT_SOURCE_DIR}/${dir} ${CMAKE_CURRENT_SOURCE_DIR}/${dir}/*)
  list(SORT children)
  foreach(child ${children})
    if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${dir}/${child}/CMakeLists.txt)
      add_subdirectory(${dir}/${child})
    endif()
  endforeach()
endfunction()
