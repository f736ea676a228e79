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
# The arguments of <function>(<target> ...) as cmake_parse_arguments left them in the caller (the
# prefix arg_): each name after <target> given, nothing left over; else a fatal error naming the
# call.
function(_topograsp_check_arguments function target)
  foreach(required IN LISTS ARGN)
    if(NOT arg_${required})
      message(FATAL_ERROR "${function}(${target}): ${required} is required")
    endif()
  endforeach()
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${function}(${target}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
endfunction()

function(topograsp_import_hand target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "SKIP_MISSING_MESHES" "FILE;NAMESPACE;HEADER;ROOT;MESH_DIR;DESCRIPTION"
                        "")
  _topograsp_check_arguments(topograsp_import_hand ${target} FILE NAMESPACE HEADER)
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

# topograsp_add_hand_program(<program> FILE <urdf-or-mjcf> DESCRIPTION <hand.json> NAME <hand>
#                            [ROOT <link-or-body>] [MESH_DIR <dir>] [SKIP_MISSING_MESHES])
#
# Builds <program>: grasp_transfer for the hand of FILE and DESCRIPTION, imported at build time
# (topograsp_import_hand) as the model <hand>::model. `<program> --hand <hand>` (its only hand,
# so the default) runs the experiment with the human demonstrations transferred to it by every
# method that runs on a free base, with every option of grasp_transfer (objects, shards, merge,
# resume, figures), judged by the built-in stepper and by MuJoCo where MuJoCo is found.
# <hand> must be a C identifier. Needs topograsp's source tree (add_subdirectory or FetchContent):
# the program's sources are not installed. docs/transfer.md, "Any hand"; README, "Your own hand".
function(topograsp_add_hand_program program)
  cmake_parse_arguments(PARSE_ARGV 1 arg "SKIP_MISSING_MESHES" "FILE;DESCRIPTION;NAME;ROOT;MESH_DIR"
                        "")
  _topograsp_check_arguments(topograsp_add_hand_program ${program} FILE DESCRIPTION NAME)
  if(NOT arg_NAME MATCHES "^[A-Za-z_][A-Za-z0-9_]*$")
    message(FATAL_ERROR "topograsp_add_hand_program(${program}): NAME \"${arg_NAME}\" is not a C "
                        "identifier (it is the hand's namespace and --hand name)")
  endif()
  # The program's sources: the source tree's apps/ (an install carries the library, not them).
  set(apps ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../apps)
  if(NOT EXISTS ${apps}/grasp_transfer/main.cpp)
    message(FATAL_ERROR "topograsp_add_hand_program(${program}): grasp_transfer's sources are not "
                        "in ${apps}: the function needs topograsp's source tree (add_subdirectory "
                        "or FetchContent); an installed topograsp does not carry the program")
  endif()
  set(hand_dir ${CMAKE_CURRENT_BINARY_DIR}/topograsp_hands/${program})
  set(hand_source ${hand_dir}/${arg_NAME}_program.cpp)
  set(compiled_source ${hand_dir}/${arg_NAME}_compiled.cpp)
  file(CONFIGURE OUTPUT ${hand_dir}/${arg_NAME}_compiled.hpp CONTENT
       "// Generated by topograsp_add_hand_program(${program}): the hand's transfer steps, compiled in\n\
// ${arg_NAME}_compiled.cpp (grasp/compiled_hand.hpp).\n\
#pragma once\n\
#include <topograsp/grasp/compiled_hand.hpp>\n\
#include \"${arg_NAME}_hand.hpp\"\n\
\n\
TOPOGRASP_EXTERN_HAND(${arg_NAME}::model);\n")
  file(CONFIGURE OUTPUT ${hand_source} CONTENT
       "// Generated by topograsp_add_hand_program(${program}): the hand of grasp_transfer --hand ${arg_NAME}.\n\
#include <grasp_transfer/program.hpp>\n\
#include \"${arg_NAME}_compiled.hpp\"\n\
\n\
TOPOGRASP_HAND_PROGRAM(\"${arg_NAME}\", ${arg_NAME}::model)\n")
  file(CONFIGURE OUTPUT ${compiled_source} CONTENT
       "// Generated by topograsp_add_hand_program(${program}): the hand's transfer steps.\n\
#include \"${arg_NAME}_compiled.hpp\"\n\
\n\
TOPOGRASP_COMPILE_HAND(${arg_NAME}::model);\n")
  # The hand's two units (the program for the hand; the hand's transfer steps, compiled apart:
  # grasp/compiled_hand.hpp) are object libraries of their own, so that they compile beside each
  # other and the program's other units (a program's sources wait for the targets it links to be
  # built), which topograsp's own build compiles where it builds grasp_transfer. They are built
  # for the program only (EXCLUDE_FROM_ALL): a program left out of "all" leaves its hand out too.
  set(unit ${program}_hand)
  set(compiled_unit ${program}_hand_compiled)
  add_library(${unit} OBJECT EXCLUDE_FROM_ALL ${hand_source})
  add_library(${compiled_unit} OBJECT EXCLUDE_FROM_ALL ${compiled_source})
  add_executable(${program} $<TARGET_OBJECTS:${unit}> $<TARGET_OBJECTS:${compiled_unit}>)
  # The hand-independent templates (the human hand's demonstrations, the arm's reach, the grasp
  # quality) are compiled once, apart from the hand's unit, which declares them compiled there
  # (TOPOGRASP_EXTERN_HAND_INDEPENDENT, grasp/hand_independent.hpp; the unit takes the definitions
  # alone: linking an object library would make it wait for that library to be built).
  if(TARGET topograsp_grasp_transfer_objects)
    target_link_libraries(${program} PRIVATE topograsp_grasp_transfer_objects
                                             topograsp_grasp_transfer_human topograsp_compiled)
    foreach(target IN ITEMS ${unit} ${compiled_unit} ${program})
      target_link_libraries(${target} PRIVATE topograsp_compiled_definitions)
    endforeach()
    set(common)
  else()
    # The rest of the program compiled here, an object library too, so that its three units
    # compile beside the hand's two.
    set(common ${program}_common)
    add_library(${common} OBJECT EXCLUDE_FROM_ALL ${apps}/grasp_transfer/main.cpp
                ${apps}/grasp_transfer/human.cpp ${apps}/grasp_transfer/compiled/hand_independent.cpp)
    target_sources(${program} PRIVATE $<TARGET_OBJECTS:${common}>)
    foreach(target IN ITEMS ${unit} ${compiled_unit} ${common} ${program})
      target_compile_definitions(${target} PRIVATE TOPOGRASP_EXTERN_HAND_INDEPENDENT)
    endforeach()
  endif()
  foreach(target IN ITEMS ${unit} ${compiled_unit} ${common} ${program})
    target_include_directories(${target} PRIVATE ${apps})
    if(TARGET topograsp::topograsp)
      target_link_libraries(${target} PRIVATE topograsp::topograsp)
    else()
      target_link_libraries(${target} PRIVATE topograsp)
    endif()
    # MuJoCo, the second judge, and qhull, the Ferrari-Canny epsilon, where they are found.
    if(TARGET topograsp_mujoco)
      target_link_libraries(${target} PRIVATE topograsp_mujoco)
    else()
      find_path(TOPOGRASP_MUJOCO_INCLUDE_DIR mujoco/mujoco.h)
      find_library(TOPOGRASP_MUJOCO_LIBRARY mujoco)
      if(TOPOGRASP_MUJOCO_INCLUDE_DIR AND TOPOGRASP_MUJOCO_LIBRARY)
        target_include_directories(${target} SYSTEM PRIVATE ${TOPOGRASP_MUJOCO_INCLUDE_DIR})
        target_link_libraries(${target} PRIVATE ${TOPOGRASP_MUJOCO_LIBRARY})
        target_compile_definitions(${target} PRIVATE TOPOGRASP_HAVE_MUJOCO)
      endif()
    endif()
    if(TARGET topograsp_qhull)
      target_link_libraries(${target} PRIVATE topograsp_qhull)
    else()
      find_package(Qhull CONFIG QUIET)
      if(TARGET Qhull::qhull_r)
        target_link_libraries(${target} PRIVATE Qhull::qhull_r)
        target_compile_definitions(${target} PRIVATE TOPOGRASP_HAVE_QHULL)
      endif()
    endif()
  endforeach()
  set(options)
  foreach(option ROOT MESH_DIR)
    if(arg_${option})
      list(APPEND options ${option} ${arg_${option}})
    endif()
  endforeach()
  if(arg_SKIP_MISSING_MESHES)
    list(APPEND options SKIP_MISSING_MESHES)
  endif()
  topograsp_import_hand(${unit} FILE ${arg_FILE} DESCRIPTION ${arg_DESCRIPTION}
                        NAMESPACE ${arg_NAME} HEADER ${arg_NAME}_hand.hpp ${options})
  # The compiled unit includes the same generated header.
  string(MAKE_C_IDENTIFIER "${unit}_${arg_NAME}_hand.hpp" stem)
  add_dependencies(${compiled_unit} topograsp_import_${stem})
  target_include_directories(${compiled_unit}
                             PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/topograsp_hands/${unit})
endfunction()
