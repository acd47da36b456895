# symcr_add_checkpointing(<target> [ANNOTATIONS <file>...] [PROGRAM <name>]
#                         [PROFILE host|device] [PREVIOUS_SCHEMA <schema file>...])
#
# Runs symcr-gen over <target>'s C and C++ sources as a build step and links the runtime.
# Every source is compiled through a generated wrapper that #includes it and appends what
# needs its declarations (ops tables, root addresses, layout checks), so roots and types with
# internal linkage work without editing the sources. The wrappers replace the sources in this
# target only (other targets may still compile the same sources). One generated
# symcr_schema.cpp holds the program's schema. Call it after all sources have been added.
#
# A source that holds a program point (checkpoint_at, restore_at) is compiled as a copy with the
# point's calls inserted, <binary dir>/symcr/<target>/tu<N>_points_<file>, which its wrapper
# includes in place of the source (generator/README.md, "Program points").
#
# The generator is, in order: the cache variable SYMCR_GEN_EXECUTABLE (a prebuilt symcr-gen,
# e.g. for sanitizer builds), or the target symcr::gen (built in this project, or imported by
# find_package(symcr)). It reads the target's flags from compile_commands.json, which this
# function enables for the target. A depfile lists every header the generator read, so editing
# an annotated header regenerates.
#
# The build's schema file (for `symcr plan <checkpoint> --schema <file>`, which needs no running
# program) is written by the generator to <binary dir>/symcr/<target>/<target>.symcr-schema, a
# path the target property SYMCR_SCHEMA_FILE holds (an output of the generation step, so other
# custom commands may depend on it), and copied after each link next to the program, to
# `$<TARGET_FILE_DIR:target>/<target>.symcr-schema`.
#
# Code size: when the runtime was built with SYMCR_OPTIMIZE_SIZE (recorded on symcr::runtime,
# also in the installed package), or when the variable SYMCR_OPTIMIZE_SIZE is set true where the
# function is called, the target is linked with section garbage collection (-Wl,--gc-sections;
# -Wl,-dead_strip on Apple). The runtime is compiled one section per function, so the program
# keeps only the runtime functions it reaches. Setting the variable false turns it off. The
# generated tables stay: they are reached from symcr_program_schema, which the runtime calls.
#
# Roots must be defined in <target>'s own sources: the sources of the static libraries it links
# (targets of this project, at any depth, as linked when the function is called) are checked,
# and a root defined there fails the build with a diagnostic naming it.
#
# PROGRAM names the program in its checkpoints (default: the calling project's PROJECT_NAME), so
# that a restore refuses a checkpoint of another program whose roots happen to have the same
# names. Builds of one program (v0 and its patched v1) must share the name.
#
# PROFILE device generates for the device profile (runtime/device, <symcr/device.hpp>) and links
# symcr::device instead of symcr::runtime: the same tables, without the heap code (ops tables,
# lifecycles, migrations) the device never calls. A member of a root whose type the device
# profile cannot hold (a string, a container, an optional, a variant, a smart pointer) fails the
# generation step with its path and the change that fixes it, as do program points. With a cross
# compiler (arm-none-eabi-g++), symcr-gen parses for that compiler's target and headers, so the
# schema records the microcontroller's layouts.
#
# PREVIOUS_SCHEMA names the schema files of earlier builds whose checkpoints this build restores
# (the release in the field, kept with the sources; or another target's SYMCR_SCHEMA_FILE in the
# same directory). Each is resolved against this build's schema by symcr-gen, with the runtime's
# own planner, and the plan is embedded: the first restore of such a checkpoint in a freshly
# started process reads it instead of planning. Other checkpoints are planned when restored, as
# without the option. Editing a listed file regenerates.
#
# A build runs one symcr-gen per checkpointed target, often over the same sources: the notes it
# prints (not its warnings or errors) are printed once per build tree, by the first target whose
# generation reaches them, and listed in <build>/symcr/shown-notes.txt (delete it to see them
# again). A generation step that fails prints all of its notes.
#
# `#pragma symcr` lines are unknown to g++, which warns under -Wall (-Wunknown-pragmas): the
# function adds -Wno-unknown-pragmas to the annotated target (only there).
include_guard(GLOBAL)

# Stops the configuration because <function> needs <tool>, with the advice that fits where symcr
# comes from: an installed package (found with find_package) was built without the tool, while in
# this build tree the option builds it. Either way <variable> may name a prebuilt executable.
function(_symcr_tool_missing function tool option variable)
  if(TARGET symcr::runtime)
    get_target_property(installed symcr::runtime IMPORTED)
  endif()
  if(installed)
    message(FATAL_ERROR "${function}: the symcr package found at ${symcr_DIR} has no ${tool}: "
                        "it was built with ${option}=OFF. Build symcr with ${option}=ON and "
                        "install it again (cmake --install <build> --component sdk), or set "
                        "${variable} to a ${tool} executable.")
  endif()
  message(FATAL_ERROR "${function}: no ${tool}. Build it (${option}=ON) or set ${variable} to a "
                      "${tool} executable.")
endfunction()

function(symcr_add_checkpointing target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "PROGRAM;PROFILE" "ANNOTATIONS;PREVIOUS_SCHEMA")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "symcr_add_checkpointing: unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET ${target})
    message(FATAL_ERROR "symcr_add_checkpointing: '${target}' is not a target")
  endif()

  if(SYMCR_GEN_EXECUTABLE)
    set(generator "${SYMCR_GEN_EXECUTABLE}")
    set(generator_dependency "${SYMCR_GEN_EXECUTABLE}")
  elseif(TARGET symcr::gen)
    set(generator "$<TARGET_FILE:symcr::gen>")
    set(generator_dependency symcr::gen)
  else()
    _symcr_tool_missing(symcr_add_checkpointing symcr-gen SYMCR_BUILD_GENERATOR
                        SYMCR_GEN_EXECUTABLE)
  endif()
  set(profile host)
  if(arg_PROFILE)
    set(profile "${arg_PROFILE}")
  endif()
  if(profile STREQUAL "device")
    set(runtime symcr::device)
  elseif(profile STREQUAL "host")
    set(runtime symcr::runtime)
  else()
    message(FATAL_ERROR "symcr_add_checkpointing: PROFILE is host or device, not '${profile}'")
  endif()
  if(NOT TARGET ${runtime})
    message(FATAL_ERROR "symcr_add_checkpointing: target ${runtime} not found")
  endif()

  get_target_property(source_dir ${target} SOURCE_DIR)
  get_target_property(binary_dir ${target} BINARY_DIR)
  get_target_property(sources ${target} SOURCES)
  set(out_dir "${binary_dir}/symcr/${target}")
  set(annotations)
  foreach(file IN LISTS arg_ANNOTATIONS)
    get_filename_component(file "${file}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND annotations "${file}")
  endforeach()

  set(previous_schemas)
  set(previous_args)
  foreach(file IN LISTS arg_PREVIOUS_SCHEMA)
    get_filename_component(file "${file}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND previous_schemas "${file}")
    list(APPEND previous_args --previous-schema "${file}")
  endforeach()

  set(inputs)
  set(wrappers)
  set(replaced)
  set(index 0)
  foreach(source IN LISTS sources)
    if(source MATCHES "^\\$<")
      continue() # generator expressions: not a plain source
    endif()
    get_filename_component(extension "${source}" LAST_EXT)
    if(NOT extension MATCHES "^\\.(c|cc|cpp|cxx|c\\+\\+|C)$")
      continue()
    endif()
    get_filename_component(path "${source}" ABSOLUTE BASE_DIR "${source_dir}")
    get_filename_component(name "${path}" NAME)
    set(wrapper "${out_dir}/tu${index}_${name}")
    math(EXPR index "${index} + 1")
    list(APPEND inputs "${path}")
    list(APPEND wrappers "${wrapper}")
    list(APPEND replaced "${source}")
  endforeach()
  if(NOT inputs)
    message(FATAL_ERROR "symcr_add_checkpointing: '${target}' has no C or C++ sources")
  endif()

  set(program "${arg_PROGRAM}")
  if(NOT program)
    set(program "${PROJECT_NAME}")
  endif()
  # Sources of the static libraries the target links (in this project, at any depth): symcr-gen
  # checks them for roots, which it could not export from there, so that such a root is a build
  # error naming it rather than silently absent from every checkpoint.
  set(library_args)
  set(library_inputs)
  set(pending_libraries)
  get_target_property(linked ${target} LINK_LIBRARIES)
  if(linked)
    list(APPEND pending_libraries ${linked})
  endif()
  set(seen_libraries)
  while(pending_libraries)
    list(POP_FRONT pending_libraries library)
    if(NOT TARGET ${library} OR library IN_LIST seen_libraries)
      continue()
    endif()
    list(APPEND seen_libraries ${library})
    get_target_property(aliased ${library} ALIASED_TARGET)
    if(aliased)
      list(APPEND pending_libraries ${aliased})
      continue()
    endif()
    get_target_property(library_type ${library} TYPE)
    get_target_property(imported ${library} IMPORTED)
    if(NOT library_type STREQUAL "STATIC_LIBRARY" OR imported OR library STREQUAL "symcr_runtime")
      continue()
    endif()
    set_target_properties(${library} PROPERTIES EXPORT_COMPILE_COMMANDS ON)
    get_target_property(library_sources ${library} SOURCES)
    get_target_property(library_dir ${library} SOURCE_DIR)
    foreach(source IN LISTS library_sources)
      get_filename_component(extension "${source}" LAST_EXT)
      if(source MATCHES "^\\$<" OR NOT extension MATCHES "^\\.(c|cc|cpp|cxx|c\\+\\+|C)$")
        continue()
      endif()
      get_filename_component(path "${source}" ABSOLUTE BASE_DIR "${library_dir}")
      list(APPEND library_args --library-source "${path}")
      list(APPEND library_inputs "${path}")
    endforeach()
    get_target_property(library_links ${library} LINK_LIBRARIES)
    if(library_links)
      list(APPEND pending_libraries ${library_links})
    endif()
  endwhile()

  set(schema "${out_dir}/symcr_schema.cpp")
  set(schema_file "${out_dir}/${target}.symcr-schema")
  set(annotation_args)
  foreach(file IN LISTS annotations)
    list(APPEND annotation_args --annotations "${file}")
  endforeach()
  add_custom_command(
    OUTPUT "${schema}" ${wrappers} "${schema_file}"
    COMMAND "${generator}" -p "${CMAKE_BINARY_DIR}" --out-dir "${out_dir}"
            --schema-file "${schema_file}" --program "${program}" --profile "${profile}"
            --depfile "${out_dir}/symcr-gen.d" --depfile-target "${schema}"
            --report-file "${out_dir}/report.txt"
            --shown-notes "${CMAKE_BINARY_DIR}/symcr/shown-notes.txt"
            ${annotation_args} ${previous_args}
            ${library_args} ${inputs}
    DEPENDS ${generator_dependency} ${inputs} ${library_inputs} ${annotations}
            ${previous_schemas}
    DEPFILE "${out_dir}/symcr-gen.d"
    COMMENT "symcr-gen: generating checkpoint code for ${target}"
    VERBATIM)
  # The wrappers replace the sources in this target only (not HEADER_FILE_ONLY, a directory-wide
  # source property): another target may still compile the same sources plainly.
  set(kept_sources ${sources})
  list(REMOVE_ITEM kept_sources ${replaced})
  set_property(TARGET ${target} PROPERTY SOURCES ${kept_sources})
  target_sources(${target} PRIVATE "${schema}" ${wrappers})
  set_target_properties(${target} PROPERTIES EXPORT_COMPILE_COMMANDS ON
    SYMCR_SCHEMA_FILE "${schema_file}")
  # OUTPUT cannot name $<TARGET_FILE_DIR>: the file is generated beside the code and copied.
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND "${CMAKE_COMMAND}" -E copy_if_different "${schema_file}"
            "$<TARGET_FILE_DIR:${target}>/${target}.symcr-schema"
    VERBATIM)
  target_link_libraries(${target} PRIVATE ${runtime})
  if(profile STREQUAL "device")
    # symcr_program_device_schema() builds its root table on first call (a root's address comes
    # from its own source's wrapper); without a thread-safe guard, that is a flag test rather
    # than libstdc++'s __cxa_guard_*, which would pull the exception unwinder into a firmware.
    set_property(SOURCE "${schema}" TARGET_DIRECTORY ${target} APPEND PROPERTY COMPILE_OPTIONS
                 $<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang,AppleClang>:-fno-threadsafe-statics>)
  endif()
  if(DEFINED SYMCR_OPTIMIZE_SIZE)
    set(optimize_size ${SYMCR_OPTIMIZE_SIZE})
  else()
    get_target_property(optimize_size ${runtime} SYMCR_OPTIMIZE_SIZE)
  endif()
  if(optimize_size)
    if(APPLE)
      target_link_options(${target} PRIVATE -Wl,-dead_strip)
    else()
      target_link_options(${target} PRIVATE -Wl,--gc-sections)
    endif()
  endif()
  target_compile_options(${target} PRIVATE
    $<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang,AppleClang>:-Wno-unknown-pragmas>
    $<$<COMPILE_LANG_AND_ID:C,GNU,Clang,AppleClang>:-Wno-unknown-pragmas>)
endfunction()
