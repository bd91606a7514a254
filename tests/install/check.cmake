# cmake -P script: install bandlight into WORK_DIR/prefix, configure and build
# the host project against it, run the host.
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
    message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK_DIR}/build"
                        "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
    message(FATAL_ERROR "configuring the host with find_package(bandlight) failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK_DIR}/build" RESULT_VARIABLE rc)
if(rc)
    message(FATAL_ERROR "building the host failed")
endif()
execute_process(COMMAND "${WORK_DIR}/build/host" "${WORK_DIR}" RESULT_VARIABLE rc)
if(rc)
    message(FATAL_ERROR "the host ran but gave the wrong answer")
endif()
# The public API's host writes, with nothing but the folder given, the config.ocio
# the command writes with its defaults.
execute_process(COMMAND "${WORK_DIR}/build/config_host" "${WORK_DIR}/host_config"
                RESULT_VARIABLE rc)
if(rc)
    message(FATAL_ERROR "the config host failed: ${rc}")
endif()
execute_process(COMMAND "${BANDLIGHT_EXE}" config --out "${WORK_DIR}/command_config"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
    message(FATAL_ERROR "bandlight config failed: ${rc}")
endif()
file(READ "${WORK_DIR}/host_config/config.ocio" _host)
file(READ "${WORK_DIR}/command_config/config.ocio" _command)
if(NOT _host STREQUAL _command OR _host STREQUAL "")
    message(FATAL_ERROR "the host's config.ocio differs from the command's")
endif()
