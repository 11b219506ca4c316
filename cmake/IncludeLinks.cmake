# indoormap_include_links(<src> <out>): what a test or benchmark source links, derived from its
# #includes (tests/ and bench/ link this, and nothing else, so that a test or benchmark of one
# module links that module and what it needs, never the whole library):
#   indoormap/<module>/...   im_<module> (with that module's own dependencies)
#   an apps/common header    the app library it belongs to (im_app_common, im_app_base)
#   opencv2/...              opencv_core opencv_imgproc opencv_imgcodecs
#   nlohmann/...             nlohmann_json::nlohmann_json
#   pcl/...                  PCL::lite (a PCL reference in a benchmark)
#   "<name>_fixtures.hpp"    a shared fixture header next to <src>: its includes count as the
#                            source's own
function(indoormap_include_links src out)
  file(STRINGS ${src} includes REGEX "^#include [\"<]")
  get_filename_component(dir ${src} DIRECTORY)
  set(links)
  foreach(line ${includes})
    if(line MATCHES "indoormap/([a-z_]+)/")
      # (${CMAKE_MATCH_1} is expanded before if() runs: test the target in its own if)
      if(TARGET im_${CMAKE_MATCH_1})
        list(APPEND links im_${CMAKE_MATCH_1})
      endif()
    elseif(line MATCHES "\"(config|plan_config|pipeline_run|objects_outputs|route_files|cli)\\.hpp\"")
      list(APPEND links im_app_common)
    elseif(line MATCHES "\"(config_reader|main_guard|map_yaml|output_set|provenance|report)\\.hpp\"")
      list(APPEND links im_app_base)
    elseif(line MATCHES "opencv2/")
      list(APPEND links opencv_core opencv_imgproc opencv_imgcodecs)
    elseif(line MATCHES "nlohmann/")
      list(APPEND links nlohmann_json::nlohmann_json)
    elseif(line MATCHES "pcl/")
      list(APPEND links PCL::lite)
    elseif(line MATCHES "\"([a-z_]+_fixtures)\\.hpp\"")
      indoormap_include_links(${dir}/${CMAKE_MATCH_1}.hpp fixture_links)
      list(APPEND links ${fixture_links})
    endif()
  endforeach()
  list(REMOVE_DUPLICATES links)
  set(${out} ${links} PARENT_SCOPE)
endfunction()
