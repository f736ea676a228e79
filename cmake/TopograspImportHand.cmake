# SPDX-License-Identifier: BSD-3-Clause
# topograsp_import_hand(<target> FILE <urdf-or-mjcf> NAMESPACE <ns> HEADER <name.hpp>
#                       [DESCRIPTION <hand.json>] [ROOT <link-or-body>] [MESH_DIR <dir>]
#                       [SKIP_MISSING_MESHES])
#
# Imports a URDF or MJCF file at build time (the tool topograsp_import_hand) into the header
# <HEADER>, which declares <ns>::links, <ns>::shapes and <ns>::frames for topograsp::make_model()
# and, with a DESCRIPTION (the hand description file: fingers, thumb, palm centre, closing
# directions, motors, held joints), <ns>::model, the complete hand; and lets <target> include it as
# #include "<HEADER>". The header is made again whenever either file changes. docs/models.md,
# "Bring your own hand".
function(topograsp_import_hand target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "SKIP_MISSING_MESHES" "FILE;NAMESPACE;HEADER;ROOT;MESH_DIR;DESCRIPTION"
                        "")
  foreach(required FILE NAMESPACE HEADER)
    if(NOT arg_${required})
      message(FATAL_ERROR "topograsp_import_hand(${target}): ${required} is required")
    endif()
  endforeach()
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "topograsp_import_hand(${target}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(TARGET topograsp_import_hand)
    set(tool topograsp_import_hand)
  elseif(TARGET topograsp::import_hand)
    set(tool topograsp::import_hand)
  else()
    message(FATAL_ERROR "topograsp_import_hand(${target}): the tool topograsp_import_hand is not "
                        "built (TOPOGRASP_BUILD_TOOLS=OFF?)")
  endif()
  get_filename_component(file ${arg_FILE} ABSOLUTE)
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/topograsp_hands/${target})
  set(header ${dir}/${arg_HEADER})
  set(options)
  if(arg_ROOT)
    list(APPEND options --root ${arg_ROOT})
  endif()
  if(arg_MESH_DIR)
    get_filename_component(mesh_dir ${arg_MESH_DIR} ABSOLUTE)
    list(APPEND options --mesh-dir ${mesh_dir})
  endif()
  if(arg_SKIP_MISSING_MESHES)
    list(APPEND options --skip-missing-meshes)
  endif()
  set(description)
  if(arg_DESCRIPTION)
    get_filename_component(description ${arg_DESCRIPTION} ABSOLUTE)
    list(APPEND options --description ${description})
  endif()
  get_filename_component(header_dir ${header} DIRECTORY)
  add_custom_command(
    OUTPUT ${header}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${header_dir}
    COMMAND ${tool} ${file} --out ${header} --namespace ${arg_NAMESPACE} ${options}
    DEPENDS ${tool} ${file} ${description}
    COMMENT "topograsp: importing ${arg_FILE} into ${arg_HEADER}"
    VERBATIM)
  string(MAKE_C_IDENTIFIER "${target}_${arg_HEADER}" stem)
  add_custom_target(topograsp_import_${stem} DEPENDS ${header})
  add_dependencies(${target} topograsp_import_${stem})
  target_include_directories(${target} PRIVATE ${dir})
  target_sources(${target} PRIVATE ${header})
endfunction()
