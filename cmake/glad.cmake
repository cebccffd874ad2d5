# The GL loader is generated at configure time by Debian's python3-glad (glad 2)
# from the Khronos XML it ships, in multi-context ("mx") mode so that each
# context backend owns its own function table. The system interpreter is named
# explicitly: a python3 earlier on PATH (pyenv, venv) does not see Debian's glad.
find_program(PENUMBRA_SYSTEM_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH REQUIRED)
set(PENUMBRA_GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
if(NOT EXISTS ${PENUMBRA_GLAD_DIR}/src/gl.c)
  execute_process(
    COMMAND ${PENUMBRA_SYSTEM_PYTHON} -m glad --reproducible --quiet
            --api gl:core=4.5 --extensions GL_KHR_debug
            --out-path ${PENUMBRA_GLAD_DIR} c --mx
    RESULT_VARIABLE glad_result
    ERROR_VARIABLE glad_error)
  if(NOT glad_result EQUAL 0)
    message(FATAL_ERROR "penumbra: generating the GL loader with ${PENUMBRA_SYSTEM_PYTHON} -m glad failed "
                        "(is Debian's python3-glad installed?): ${glad_error}")
  endif()
endif()
add_library(penumbra_glad STATIC ${PENUMBRA_GLAD_DIR}/src/gl.c)
target_include_directories(penumbra_glad SYSTEM PUBLIC ${PENUMBRA_GLAD_DIR}/include)
set_target_properties(penumbra_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
