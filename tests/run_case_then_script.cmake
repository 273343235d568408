# Runs a shipped case, then a script that judges its output folder (SCRIPT OUT ARGS...), and
# fails unless both exit 0: for validations whose comparison lives in a script.
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${EXE} run ${CASE} --out ${OUT} --quiet RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pilempm run ${CASE} exited with ${rc}")
endif()
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND python3 ${SCRIPT} ${OUT} ${args} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SCRIPT} on ${OUT} exited with ${rc}")
endif()
