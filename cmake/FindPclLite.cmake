# Finds Debian's PCL 1.13 headers and the few libraries we use, without PCL's CMake config:
# that config drags in VTK, whose Debian targets reference MPI::MPI_C and break configuration
# unless MPI development files are installed. Defines imported target PCL::lite.
find_path(PCL_LITE_INCLUDE_DIR pcl/point_types.h PATH_SUFFIXES pcl-1.13 REQUIRED)
set(_pcl_libs)
foreach(component common io io_ply filters search kdtree octree)
  find_library(PCL_LITE_${component}_LIBRARY pcl_${component} REQUIRED)
  list(APPEND _pcl_libs ${PCL_LITE_${component}_LIBRARY})
endforeach()
find_package(Boost REQUIRED)
if(NOT TARGET PCL::lite)
  add_library(PCL::lite INTERFACE IMPORTED)
  set_target_properties(PCL::lite PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${PCL_LITE_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${_pcl_libs};Boost::headers;Eigen3::Eigen")
endif()
