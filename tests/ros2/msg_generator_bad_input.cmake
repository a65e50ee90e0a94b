# Runs the .msg generator on malformed definitions: each must exit 2 with one line
# "msg_generator: FILE:LINE: what" and leave no output file.
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR}/pkg)
set(cases "int32 x\nfoo_msgs/Nope y\n|2|unknown type foo_msgs/Nope"
          "int32\n|1|a field needs a type and a name"
          "wstring w\n|1|wstring is not supported"
          "int32 a\nint32 a\n|2|a defined twice"
          "int32[<=x] v\n|1|not a bound"
          "float64 Q=abc\n|1|not a number")
foreach(c IN LISTS cases)
  string(REPLACE "|" ";" parts "${c}")
  list(GET parts 0 text)
  list(GET parts 1 line)
  list(GET parts 2 what)
  file(WRITE ${DIR}/pkg/Bad.msg "${text}")
  execute_process(COMMAND ${GENERATOR} ${DIR}/out.hpp ${DIR}/pkg/Bad.msg RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "exit ${rc} (not 2) for:\n${text}")
  endif()
  if(NOT err MATCHES "^msg_generator: [^\n]*/pkg/Bad.msg:${line}: ${what}[^\n]*\n$")
    message(FATAL_ERROR "unexpected message '${err}' for:\n${text}")
  endif()
  if(EXISTS ${DIR}/out.hpp)
    message(FATAL_ERROR "an output file was written for:\n${text}")
  endif()
endforeach()
