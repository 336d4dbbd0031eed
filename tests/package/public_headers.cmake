# The public API stands alone: installs the build tree into a fresh prefix, checks that it holds
# exactly the source tree's include/ folder (no internal header), then compiles one translation
# unit that includes every installed header with only the installed include path and the public
# dependencies (Vulkan and GLM, from the system).
set(prefix "${WORK_DIR}/prefix-headers")
file(REMOVE_RECURSE "${prefix}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}"
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "install failed: ${err}")
endif()

set(include_root "${prefix}/include/rasterliquids")
file(GLOB_RECURSE installed RELATIVE "${include_root}" "${prefix}/include/*")
file(GLOB_RECURSE public RELATIVE "${SOURCE_DIR}/include" "${SOURCE_DIR}/include/*.h")
list(SORT installed)
list(SORT public)
if(NOT installed STREQUAL public)
  message(FATAL_ERROR "the install's headers are not the public ones:\ninstalled: ${installed}\npublic: ${public}")
endif()
list(LENGTH public count)
if(count LESS 10)
  message(FATAL_ERROR "only ${count} public headers found under ${SOURCE_DIR}/include")
endif()

set(unit "${WORK_DIR}/all_public_headers.cpp")
set(text "// Generated: every installed header, in one translation unit.\n")
foreach(header ${installed})
  string(APPEND text "#include <${header}>\n")
endforeach()
string(APPEND text "int main() { return 0; }\n")
file(WRITE "${unit}" "${text}")
# With the project's own warnings, as errors (Vulkan's `VkStruct s{VK_STRUCTURE_TYPE_...}` idiom
# leaves the other members to zero, which -Wmissing-field-initializers would flag).
execute_process(COMMAND "${CXX}" -std=c++20 -fsyntax-only -Wall -Wextra -Wpedantic -Wno-missing-field-initializers
                        -Werror -I "${include_root}" "${unit}"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the installed headers do not compile on their own:\n${out}${err}")
endif()
message(STATUS "${count} public headers compile with only ${include_root}")
