# Davison's postponed update (thesis appendix C), owned by the "postponed" work item.
# Included by libmrolr/src/slam/CMakeLists.txt, which adds these sources to mrolr_slam; the tests in
# tests/slam_postponed include it directly while mrolr_slam does not exist.
set(MROLR_SLAM_POSTPONED_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/PostponedTracker.cpp)
