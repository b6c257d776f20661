# The consumer tests' fixture: a campaign made by the reduced library (consumer-campaign),
# calibrated by impact-calibrate and exported by impact-export, as a user would.
# Variables: CAMPAIGN, CALIBRATE, EXPORT (the three executables), WORK_DIR.
file(REMOVE_RECURSE ${WORK_DIR})
function(run_step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  message(STATUS "${ARGN}\n${output}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "step failed (exit ${result})")
  endif()
endfunction()
run_step(${CAMPAIGN} ${WORK_DIR}/campaign)
# The noise-free Kuwabara-Kono campaign fit converges slowly (158 iterations to a relative
# step of 1e-12), hence the iteration limit above the default 100.
run_step(${CALIBRATE} --campaign ${WORK_DIR}/campaign --output ${WORK_DIR}/calibration.json
         --laws kuwabara-kono,tsuji --max-iterations 1000 --quiet)
# The restitution table (and the Simbody and LAMMPS runs of its law): Hunt-Crossley damping on
# Thornton's spring from the material, which yields at every velocity of the fixture.
run_step(${EXPORT} --campaign ${WORK_DIR}/campaign --calibration ${WORK_DIR}/calibration.json
         --output ${WORK_DIR}/export --law hunt-crossley-thornton-material)
# The same for Kuwabara-Kono damping on Thornton's spring from the material: the force
# F_s + A k_t x' of the table's law in the same two tools.
run_step(${EXPORT} --campaign ${WORK_DIR}/campaign --calibration ${WORK_DIR}/calibration.json
         --output ${WORK_DIR}/export-kuwabara-kono --law kuwabara-kono-thornton-material)
