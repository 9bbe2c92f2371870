# ROS 1 from Debian 12, found without catkin's package configs: rosbag_storage's config pulls in
# pluginlib and ament, which run Python modules at configure time. Defines MrolrRos1_FOUND and the
# imported target MrolrRos1::ros1 (roscpp, rosbag_storage and what they link; message headers).
find_path(MROLR_ROS1_INCLUDE_DIR ros/ros.h)
find_path(MROLR_ROSBAG_INCLUDE_DIR rosbag/bag.h)
find_path(MROLR_ROS1_MSGS_DIR sensor_msgs/Image.h)
# rosbag/bag.h includes pluginlib, which Debian installs ROS 2 style, one folder deeper
find_path(MROLR_PLUGINLIB_INCLUDE_DIR pluginlib/class_loader.hpp PATH_SUFFIXES pluginlib)
find_path(MROLR_CLASS_LOADER_INCLUDE_DIR class_loader/class_loader.hpp PATH_SUFFIXES class_loader)
find_path(MROLR_RCUTILS_INCLUDE_DIR rcutils/types.h PATH_SUFFIXES rcutils)
find_path(MROLR_RCPPUTILS_INCLUDE_DIR rcpputils/shared_library.hpp PATH_SUFFIXES rcpputils)
find_path(MROLR_AMENT_INDEX_INCLUDE_DIR ament_index_cpp/get_package_prefix.hpp PATH_SUFFIXES ament_index_cpp)
set(_mrolr_ros1_libs roscpp rosbag_storage rostime roscpp_serialization cpp_common roslz4
    rosconsole xmlrpcpp console_bridge class_loader ament_index_cpp tf2)
set(_mrolr_ros1_paths "")
set(MrolrRos1_FOUND TRUE)
foreach(_lib ${_mrolr_ros1_libs})
  find_library(MROLR_ROS1_LIB_${_lib} ${_lib})
  if(NOT MROLR_ROS1_LIB_${_lib})
    set(MrolrRos1_FOUND FALSE)
  endif()
  list(APPEND _mrolr_ros1_paths ${MROLR_ROS1_LIB_${_lib}})
endforeach()
set(_mrolr_ros1_includes "")
foreach(_dir MROLR_ROS1_INCLUDE_DIR MROLR_ROSBAG_INCLUDE_DIR MROLR_ROS1_MSGS_DIR
    MROLR_PLUGINLIB_INCLUDE_DIR MROLR_CLASS_LOADER_INCLUDE_DIR MROLR_RCUTILS_INCLUDE_DIR
    MROLR_RCPPUTILS_INCLUDE_DIR MROLR_AMENT_INDEX_INCLUDE_DIR)
  if(${_dir})
    list(APPEND _mrolr_ros1_includes ${${_dir}})
  endif()
endforeach()
list(REMOVE_DUPLICATES _mrolr_ros1_includes)
if(NOT MROLR_ROS1_INCLUDE_DIR OR NOT MROLR_ROSBAG_INCLUDE_DIR OR NOT MROLR_ROS1_MSGS_DIR
   OR NOT MROLR_PLUGINLIB_INCLUDE_DIR OR NOT MROLR_CLASS_LOADER_INCLUDE_DIR)
  set(MrolrRos1_FOUND FALSE)
endif()
if(MrolrRos1_FOUND)
  find_package(Boost REQUIRED COMPONENTS filesystem system chrono thread)
  if(NOT TARGET MrolrRos1::ros1)
    add_library(MrolrRos1::ros1 INTERFACE IMPORTED)
    set_target_properties(MrolrRos1::ros1 PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${_mrolr_ros1_includes}"
      INTERFACE_LINK_LIBRARIES "${_mrolr_ros1_paths};Boost::filesystem;Boost::system;Boost::chrono;Boost::thread")
  endif()
endif()
