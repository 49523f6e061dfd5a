# Each layer's internal headers are its own: a layer's target sees src/LAYER/ as "LAYER/..." and
# nothing else of src/, so an include of another layer's internals fails to compile. A layer
# shares the few internals the layers above it build on (SHARED: gl's GL objects with the
# renderer and the viewer, geometry's exact predicates with the oracles and collision) with the
# targets that link it, in the build tree only; the installed package has only include/vissort.
#
#   vissort_internal_headers(TARGET LAYER [SHARED header ...])
#
# Both are directories of symbolic links in the build tree: internal/LAYER/LAYER -> src/LAYER,
# and internal-shared/LAYER/LAYER/HEADER -> src/LAYER/HEADER.
function(vissort_internal_headers target layer)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "SHARED")
  set(private_root ${PROJECT_BINARY_DIR}/internal/${layer})
  if(NOT EXISTS ${private_root}/${layer})
    file(MAKE_DIRECTORY ${private_root})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/src/${layer} ${private_root}/${layer} SYMBOLIC)
  endif()
  target_include_directories(${target} PRIVATE ${private_root})
  if(arg_SHARED)
    set(shared_root ${PROJECT_BINARY_DIR}/internal-shared/${layer})
    file(MAKE_DIRECTORY ${shared_root}/${layer})
    foreach(header IN LISTS arg_SHARED)
      if(NOT EXISTS ${PROJECT_SOURCE_DIR}/src/${layer}/${header})
        message(FATAL_ERROR "vissort_internal_headers: src/${layer}/${header} does not exist")
      endif()
      if(NOT EXISTS ${shared_root}/${layer}/${header})
        file(CREATE_LINK ${PROJECT_SOURCE_DIR}/src/${layer}/${header}
             ${shared_root}/${layer}/${header} SYMBOLIC)
      endif()
    endforeach()
    target_include_directories(${target} INTERFACE $<BUILD_INTERFACE:${shared_root}>)
  endif()
endfunction()
