# penumbra_bundle(OUTPUT <file> MODULE <module>
#                 [TARGET gl450|vulkan|es310|hlsl|msl] [SHADER_MODEL 5.0|5.1|6.0] [BARE] [GLSL_ROOT <dir>]
#                 [REGISTER_SHIFT t=N,s=N,u=N,b=N] [REGISTER_SPACE N])
#
# Writes OUTPUT at build time with `penumbra bundle MODULE --target TARGET` (docs/cli.md): the module and
# its includes in one GLSL file, or its HLSL or MSL export; BARE, SHADER_MODEL, REGISTER_SHIFT and
# REGISTER_SPACE are the command's --bare, --shader-model, --register-shift and --register-space (an HLSL
# export in your register plan: a space needs SHADER_MODEL 5.1 or 6.0). MODULE is a path under the glsl root (fast_pcss.glsl, passes/blur.comp); the root is
# the tool's own modules, or GLSL_ROOT, a copy of glsl/ (relative: to the calling CMakeLists' directory). A
# relative OUTPUT is under the current binary directory. The command runs again when the tool or any file
# under the root changes; OUTPUT is built when a target of the same directory lists it as a source (or an
# add_custom_target DEPENDS on it).
#
# The tool is penumbra::penumbra: the installed one after find_package(penumbra), or the `penumbra` target
# when this file is included by penumbra's own CMakeLists.txt (in tree, or a checkout added with
# add_subdirectory or FetchContent). A bad call stops the configure step, naming the argument.
function(penumbra_bundle)
  cmake_parse_arguments(PARSE_ARGV 0 arg "BARE" "OUTPUT;MODULE;TARGET;SHADER_MODEL;GLSL_ROOT;REGISTER_SHIFT;REGISTER_SPACE"
                        "")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "penumbra_bundle: '${arg_UNPARSED_ARGUMENTS}': not an argument it takes; expected "
                        "OUTPUT, MODULE, TARGET, SHADER_MODEL, BARE, GLSL_ROOT, REGISTER_SHIFT or REGISTER_SPACE")
  endif()
  foreach(keyword IN LISTS arg_KEYWORDS_MISSING_VALUES)
    message(FATAL_ERROR "penumbra_bundle: ${keyword} without a value: expected ${keyword} <value>")
  endforeach()
  foreach(keyword OUTPUT MODULE)
    if("${arg_${keyword}}" STREQUAL "")
      message(FATAL_ERROR "penumbra_bundle: no ${keyword}: expected OUTPUT <file> MODULE <module under the glsl root>")
    endif()
  endforeach()
  if(NOT TARGET penumbra::penumbra)
    message(FATAL_ERROR "penumbra_bundle: no penumbra::penumbra in this directory: expected find_package(penumbra) "
                        "or add_subdirectory(<penumbra checkout>) before the call")
  endif()

  if(NOT DEFINED arg_TARGET)
    set(arg_TARGET gl450)  # the command's default
  endif()
  set(targets gl450 vulkan es310 hlsl msl)
  if(NOT arg_TARGET IN_LIST targets)
    list(JOIN targets ", " expected)
    message(FATAL_ERROR "penumbra_bundle: TARGET '${arg_TARGET}': expected one of ${expected}")
  endif()
  set(options --target ${arg_TARGET})
  if(DEFINED arg_SHADER_MODEL)
    if(NOT arg_TARGET STREQUAL "hlsl" OR NOT arg_SHADER_MODEL MATCHES "^(5[.]0|5[.]1|6[.]0)$")
      message(FATAL_ERROR "penumbra_bundle: SHADER_MODEL '${arg_SHADER_MODEL}': expected 5.0, 5.1 or 6.0, with TARGET hlsl")
    endif()
    list(APPEND options --shader-model ${arg_SHADER_MODEL})
  endif()
  # The register plan (the command checks the values again, and a space against the shader model).
  if(DEFINED arg_REGISTER_SHIFT)
    if(NOT arg_TARGET STREQUAL "hlsl" OR NOT arg_REGISTER_SHIFT MATCHES "^[tsub]=[0-9]+(,[tsub]=[0-9]+)*$")
      message(FATAL_ERROR "penumbra_bundle: REGISTER_SHIFT '${arg_REGISTER_SHIFT}': expected KIND=N[,KIND=N...] "
                          "(KIND t, s, u or b; e.g. t=16,u=32,b=48), with TARGET hlsl")
    endif()
    list(APPEND options --register-shift ${arg_REGISTER_SHIFT})
  endif()
  if(DEFINED arg_REGISTER_SPACE)
    if(NOT arg_TARGET STREQUAL "hlsl" OR NOT arg_REGISTER_SPACE MATCHES "^[0-9]+$")
      message(FATAL_ERROR "penumbra_bundle: REGISTER_SPACE '${arg_REGISTER_SPACE}': expected a space number, with "
                          "TARGET hlsl")
    endif()
    if(NOT arg_REGISTER_SPACE EQUAL 0 AND NOT arg_SHADER_MODEL MATCHES "^(5[.]1|6[.]0)$")
      message(FATAL_ERROR "penumbra_bundle: REGISTER_SPACE ${arg_REGISTER_SPACE}: shader model 5.0 has no register "
                          "spaces: expected SHADER_MODEL 5.1 or 6.0")
    endif()
    list(APPEND options --register-space ${arg_REGISTER_SPACE})
  endif()
  if(arg_BARE)
    if(arg_TARGET STREQUAL "hlsl" OR arg_TARGET STREQUAL "msl")
      message(FATAL_ERROR "penumbra_bundle: BARE with TARGET ${arg_TARGET}: expected a GLSL target (gl450, vulkan, es310)")
    endif()
    list(APPEND options --bare)
  endif()

  if(DEFINED arg_GLSL_ROOT)
    cmake_path(ABSOLUTE_PATH arg_GLSL_ROOT BASE_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR} NORMALIZE OUTPUT_VARIABLE root)
    if(NOT IS_DIRECTORY "${root}")
      message(FATAL_ERROR "penumbra_bundle: GLSL_ROOT '${arg_GLSL_ROOT}': expected an existing directory (a copy of glsl/)")
    endif()
  else()
    get_target_property(root penumbra::penumbra PENUMBRA_GLSL_DIR)
  endif()
  # The module under the root (issue 54 X7: ../outside.glsl configured, then failed at build).
  cmake_path(ABSOLUTE_PATH arg_MODULE BASE_DIRECTORY "${root}" NORMALIZE OUTPUT_VARIABLE module_path)
  cmake_path(IS_PREFIX root "${module_path}" NORMALIZE module_under_root)
  if(IS_ABSOLUTE "${arg_MODULE}" OR NOT module_under_root OR NOT EXISTS "${module_path}" OR IS_DIRECTORY "${module_path}")
    message(FATAL_ERROR "penumbra_bundle: MODULE '${arg_MODULE}': no such file under the glsl root ${root}: "
                        "expected a module's path relative to it, e.g. fast_pcss.glsl or passes/blur.comp")
  endif()
  # HLSL and MSL export a module through its export entry, or a pass itself (issue 54 X8).
  if(arg_TARGET STREQUAL "hlsl" OR arg_TARGET STREQUAL "msl")
    cmake_path(GET module_path EXTENSION LAST_ONLY module_extension)
    cmake_path(GET module_path STEM LAST_ONLY module_stem)
    if(module_extension STREQUAL ".glsl")
      if(NOT EXISTS "${root}/exports/${module_stem}.comp")
        message(FATAL_ERROR "penumbra_bundle: MODULE '${arg_MODULE}' with TARGET ${arg_TARGET}: the module has no export "
                            "entry exports/${module_stem}.comp: expected a technique's module (fast_pcss.glsl, …) or a "
                            "pass (passes/….comp)")
      endif()
    elseif(NOT module_extension MATCHES "^[.](comp|vert|frag)$")
      message(FATAL_ERROR "penumbra_bundle: MODULE '${arg_MODULE}' with TARGET ${arg_TARGET}: expected a module (.glsl) "
                          "or a pass (.comp, .vert, .frag), not a header")
    endif()
  endif()

  # OUTPUT one file, not a list and not a directory (issue 54 X6, X8).
  if(arg_OUTPUT MATCHES ";")
    message(FATAL_ERROR "penumbra_bundle: OUTPUT '${arg_OUTPUT}': a list (';'): expected one file")
  endif()
  cmake_path(ABSOLUTE_PATH arg_OUTPUT BASE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR} NORMALIZE OUTPUT_VARIABLE output)
  if(IS_DIRECTORY "${output}")
    message(FATAL_ERROR "penumbra_bundle: OUTPUT '${arg_OUTPUT}': ${output} is a directory: expected a file")
  endif()
  cmake_path(GET output PARENT_PATH output_dir)
  file(MAKE_DIRECTORY ${output_dir})
  # Any file of the root may be included by the module (or be its export entry).
  file(GLOB_RECURSE root_files CONFIGURE_DEPENDS LIST_DIRECTORIES false ${root}/*)
  list(JOIN options " " shown_options)
  add_custom_command(
    OUTPUT ${output}
    COMMAND penumbra::penumbra bundle ${arg_MODULE} --glsl-root ${root} ${options} -o ${output}
    DEPENDS penumbra::penumbra ${root_files}
    COMMENT "penumbra bundle ${arg_MODULE} ${shown_options}"
    VERBATIM)
endfunction()
