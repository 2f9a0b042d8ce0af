# Fails when a user-visible string has no translation in TS, including strings that are in the
# sources but not yet in the .ts file: it runs lupdate on a copy, then lrelease.
# cmake -DLUPDATE= -DLRELEASE= -DLUPDATE_PROJECT= -DGENERATOR= -DTS= -DWORK= -P check_translations.cmake
file(MAKE_DIRECTORY "${WORK}")
get_filename_component(_name "${TS}" NAME)
set(_copy "${WORK}/${_name}")
execute_process(COMMAND "${CMAKE_COMMAND}" -DIN_FILE=${LUPDATE_PROJECT} -DOUT_FILE=${WORK}/project.json
                        -P "${GENERATOR}" COMMAND_ERROR_IS_FATAL ANY)
file(COPY_FILE "${TS}" "${_copy}")
execute_process(COMMAND "${LUPDATE}" -project "${WORK}/project.json" -ts "${_copy}" -no-obsolete -locations none
                OUTPUT_QUIET ERROR_QUIET COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND "${LRELEASE}" "${_copy}" -qm "${WORK}/check.qm" OUTPUT_VARIABLE _report
                COMMAND_ERROR_IS_FATAL ANY)

# List the sources whose translation is missing, so the message says what to translate.
file(READ "${_copy}" _ts)
string(REGEX MATCHALL "<source>[^<]*</source>[ \r\n\t]*<translation type=\"unfinished\"" _missing "${_ts}")
if(_missing OR NOT _report MATCHES "finished and 0 unfinished")
  string(REGEX REPLACE "<translation type=\"unfinished\"" "" _missing "${_missing}")
  string(REGEX REPLACE "[ \r\n\t]*</?source>[ \r\n\t]*" "\n  " _missing "${_missing}")
  message(FATAL_ERROR "${_name} lacks translations (run the update_translations target, then translate):${_missing}\n${_report}")
endif()
message(STATUS "${_name}: every string is translated")
