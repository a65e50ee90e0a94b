# Helpers of the build-time generators run with `cmake -P` (world/embed_scenarios.cmake,
# sim/embed_model.cmake, robot/ur5_parameters.cmake): a file as a C++ byte list, and
# writing a generated file only when its text changes (keeps rebuilds minimal).

# rtamp_bytes_literal(FILE OUT_BYTES OUT_SIZE): OUT_BYTES is FILE's bytes as
# "0x..,0x..," in lines of 32 (ready for `{ ${bytes}0x00 }`), OUT_SIZE its length.
function(rtamp_bytes_literal file out_bytes out_size)
  file(READ "${file}" hex HEX)
  string(LENGTH "${hex}" hexlen)
  math(EXPR size "${hexlen} / 2")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
  string(REGEX REPLACE "((0x[0-9a-f][0-9a-f],){32})" "\\1\n    " bytes "${bytes}")
  set(${out_bytes} "${bytes}" PARENT_SCOPE)
  set(${out_size} "${size}" PARENT_SCOPE)
endfunction()

# rtamp_write_if_changed(PATH CONTENT)
function(rtamp_write_if_changed path content)
  if(EXISTS "${path}")
    file(READ "${path}" old)
    if(old STREQUAL content)
      return()
    endif()
  endif()
  file(WRITE "${path}" "${content}")
endfunction()
