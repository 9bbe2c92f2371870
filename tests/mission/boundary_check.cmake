# The robot/world boundary: no file of the robot side (libmrolr/src/mission,
# libmrolr/include/mrolr/mission) includes a header of the simulator (mrolr/sim) or of the world
# (mrolr/world). Run by ctest as `cmake -DROOT=<source dir> -P boundary_check.cmake`; fails naming
# every offending line. (That mission links neither library is checked when configuring:
# libmrolr/CMakeLists.txt.)
file(GLOB_RECURSE robot_side
  ${ROOT}/libmrolr/src/mission/*.cpp ${ROOT}/libmrolr/src/mission/*.h
  ${ROOT}/libmrolr/include/mrolr/mission/*.h)
if(NOT robot_side)
  message(FATAL_ERROR "no robot-side sources found under ${ROOT} (wrong ROOT?)")
endif()
set(bad "")
foreach(f ${robot_side})
  file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include")
  foreach(line ${lines})
    if(line MATCHES "mrolr/(sim|world)/")
      list(APPEND bad "${f}: ${line}")
    endif()
  endforeach()
endforeach()
if(bad)
  string(REPLACE ";" "\n  " bad "${bad}")
  message(FATAL_ERROR "the robot side includes the simulator or the world:\n  ${bad}")
endif()
list(LENGTH robot_side n)
message(STATUS "robot/world boundary: ${n} robot-side files, no sim or world include")
