# Configure-time checks of the module graph.
#
# indoormap_check_no_pcl(<target>...): none of the targets may see PCL when it compiles. A target
# sees what it links (PUBLIC and PRIVATE) and, recursively, the usage requirements of those
# (their INTERFACE_LINK_LIBRARIES). A $<LINK_ONLY:...> entry (a static library's PRIVATE
# dependency, e.g. im_cloud_io's PCL::lite) only links and brings no include path, so it is not
# followed. Fails the configuration naming the offender and the chain that reaches PCL.

# Strips the generator expressions we know from one link item; sets out to "" for link-only items.
function(_indoormap_link_item item out)
  if(item MATCHES "^\\$<LINK_ONLY:")
    set(${out} "" PARENT_SCOPE)
    return()
  endif()
  if(item MATCHES "^\\$<BUILD_INTERFACE:(.*)>$")
    set(item "${CMAKE_MATCH_1}")
  elseif(item MATCHES "^\\$<")
    set(item "")  # other generator expressions ($<INSTALL_INTERFACE:...>, ...) carry no target
  endif()
  if(item AND TARGET "${item}")
    get_target_property(aliased "${item}" ALIASED_TARGET)
    if(aliased)
      set(item "${aliased}")
    endif()
  endif()
  set(${out} "${item}" PARENT_SCOPE)
endfunction()

# True when a target's include directories hold PCL's.
function(_indoormap_has_pcl_includes target property out)
  set(found FALSE)
  get_target_property(dirs "${target}" ${property})
  if(dirs AND PCL_LITE_INCLUDE_DIR)
    foreach(d ${dirs})
      if(d STREQUAL PCL_LITE_INCLUDE_DIR)
        set(found TRUE)
      endif()
    endforeach()
  endif()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

function(indoormap_check_no_pcl)
  foreach(root ${ARGN})
    if(NOT TARGET ${root})
      message(FATAL_ERROR "indoormap_check_no_pcl: no target ${root}")
    endif()
    _indoormap_has_pcl_includes(${root} INCLUDE_DIRECTORIES own)
    if(own)
      message(FATAL_ERROR "${root} must build without PCL, but PCL's headers "
                          "(${PCL_LITE_INCLUDE_DIR}) are on its include path")
    endif()
    # Breadth-first over (target, chain) pairs; the root's own links first.
    get_target_property(direct ${root} LINK_LIBRARIES)
    set(queue)
    set(chains)
    set(seen)
    if(direct)
      foreach(item ${direct})
        _indoormap_link_item("${item}" dep)
        if(dep)
          list(APPEND queue "${dep}")
          list(APPEND chains "${root} -> ${dep}")
        endif()
      endforeach()
    endif()
    while(queue)
      list(POP_FRONT queue dep)
      list(POP_FRONT chains chain)
      if(dep IN_LIST seen)
        continue()
      endif()
      list(APPEND seen "${dep}")
      if(dep STREQUAL "PCL::lite")
        message(FATAL_ERROR "${root} must build without PCL (only im_cloud_io may see it), but it "
                            "reaches PCL: ${chain}")
      endif()
      if(NOT TARGET "${dep}")
        continue()  # a plain library file or flag
      endif()
      _indoormap_has_pcl_includes("${dep}" INTERFACE_INCLUDE_DIRECTORIES pcl_dirs)
      if(pcl_dirs)
        message(FATAL_ERROR "${root} must build without PCL, but ${dep} puts PCL's headers on "
                            "its include path: ${chain}")
      endif()
      get_target_property(next "${dep}" INTERFACE_LINK_LIBRARIES)
      if(next)
        foreach(item ${next})
          _indoormap_link_item("${item}" next_dep)  # not "n": if(n) reads N, a false constant
          if(next_dep)
            list(APPEND queue "${next_dep}")
            list(APPEND chains "${chain} -> ${next_dep}")
          endif()
        endforeach()
      endif()
    endwhile()
  endforeach()
endfunction()
