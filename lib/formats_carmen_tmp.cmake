# im_formats_carmen: the streaming CARMEN log reader (plain or gzip text, read with zlib). Needs core
# and zlib only. Temporary home: the lead folds src/carmen.cpp into im_formats (lib/formats) when
# merging, and then removes this file and its include in the top-level CMakeLists.txt.
find_package(ZLIB REQUIRED)
add_library(im_formats_carmen ${CMAKE_CURRENT_LIST_DIR}/formats/src/carmen.cpp)
add_library(indoormap::formats_carmen ALIAS im_formats_carmen)
target_include_directories(im_formats_carmen PUBLIC ${CMAKE_CURRENT_LIST_DIR}/formats/include)
target_link_libraries(im_formats_carmen PUBLIC im_core PRIVATE ZLIB::ZLIB)

# tests/CMakeLists.txt links the im_<module> targets of its list; until the fold, the laser tests
# (test_carmen) get the reader here, once every directory is configured.
function(im_formats_carmen_link_tests)
  foreach(t test_carmen)
    if(TARGET ${t})
      target_link_libraries(${t} PRIVATE im_formats_carmen)
    endif()
  endforeach()
endfunction()
cmake_language(DEFER DIRECTORY ${CMAKE_SOURCE_DIR} CALL im_formats_carmen_link_tests)
