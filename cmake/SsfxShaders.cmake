# ssfx_add_shaders(TARGET <target> SOURCE_DIR <dir> SHADERS <file>...)
#
# Compiles each GLSL file <dir>/<file> to SPIR-V at build time (glslc, Vulkan 1.3, -O,
# warnings as errors) as comma-separated words in <binary dir>/generated/<target>/shaders/
# <file>.inc, which the target's sources include as the body of a `const std::uint32_t[]`
# (see ssfx/vk/compute.hpp: makeShaderModule). glslc writes a depfile, so a change to an
# #include'd file rebuilds the shaders that include it. SPIRV_DIR <dir>: also write each as a
# binary <dir>/<file>.spv (installed for integrators). VARIANT <name> <defines> [<name>
# <defines>]...: also compile each with -D<define>=1 for each of the comma-separated <defines>
# as <file>.<name>.inc (and .spv): e.g. the GPU passes' hardware mode, which drops the model's
# exact arithmetic (docs/gpu.md). NO_PLAIN: the variants only.
function(ssfx_add_shaders)
  cmake_parse_arguments(ARG "NO_PLAIN" "TARGET;SOURCE_DIR;SPIRV_DIR" "SHADERS;VARIANT" ${ARGN})
  if(NOT ARG_TARGET OR NOT ARG_SOURCE_DIR OR NOT ARG_SHADERS)
    message(FATAL_ERROR "ssfx_add_shaders: TARGET, SOURCE_DIR and SHADERS are required")
  endif()
  set(out ${CMAKE_CURRENT_BINARY_DIR}/generated/${ARG_TARGET})
  set(incs)
  set(variants)
  if(NOT ARG_NO_PLAIN)
    set(variants "_")  # "_": the plain build
  endif()
  set(defines_ "")
  list(LENGTH ARG_VARIANT nvariant)
  math(EXPR odd "${nvariant} % 2")
  if(odd)
    message(FATAL_ERROR "ssfx_add_shaders: VARIANT takes pairs <name> <defines>")
  endif()
  while(ARG_VARIANT)
    list(POP_FRONT ARG_VARIANT vname vdefines)
    list(APPEND variants ${vname})
    string(REPLACE "," ";" vdefines "${vdefines}")
    set(defines_${vname})
    foreach(d ${vdefines})
      list(APPEND defines_${vname} -D${d}=1)
    endforeach()
  endwhile()
  foreach(shader ${ARG_SHADERS})
    foreach(v ${variants})
      if(v STREQUAL "_")
        set(stem ${shader})
      else()
        set(stem ${shader}.${v})
      endif()
      set(inc ${out}/shaders/${stem}.inc)
      add_custom_command(OUTPUT ${inc}
        COMMAND ${CMAKE_COMMAND} -E make_directory ${out}/shaders
        COMMAND Vulkan::glslc --target-env=vulkan1.3 -O -Werror -mfmt=num ${defines_${v}} -I ${ARG_SOURCE_DIR}
                -MD -MF ${inc}.d -o ${inc} ${ARG_SOURCE_DIR}/${shader}
        DEPENDS ${ARG_SOURCE_DIR}/${shader}
        DEPFILE ${inc}.d
        COMMENT "glslc ${stem}"
        VERBATIM)
      list(APPEND incs ${inc})
      if(ARG_SPIRV_DIR)  # also the binary module, for integrators (installed under share/ssfx/shaders)
        set(spv ${ARG_SPIRV_DIR}/${stem}.spv)
        add_custom_command(OUTPUT ${spv}
          COMMAND ${CMAKE_COMMAND} -E make_directory ${ARG_SPIRV_DIR}
          COMMAND Vulkan::glslc --target-env=vulkan1.3 -O -Werror ${defines_${v}} -I ${ARG_SOURCE_DIR} -o ${spv}
                  ${ARG_SOURCE_DIR}/${shader}
          DEPENDS ${inc}
          COMMENT "glslc ${stem} (SPIR-V file)"
          VERBATIM)
        list(APPEND incs ${spv})
      endif()
    endforeach()
  endforeach()
  target_sources(${ARG_TARGET} PRIVATE ${incs})
  target_include_directories(${ARG_TARGET} PRIVATE ${out})
endfunction()
