# Verification cases of the pile wave analysis (issue 2, checks 1-6).
pilempm_case_test(verify_rigid_ram cases/verification/rigid-ram.yaml verification)
pilempm_case_test(verify_elastic_ram cases/verification/elastic-ram.yaml verification)
pilempm_case_test(verify_toe_reflection_free cases/verification/toe-reflection-free.yaml verification)
pilempm_case_test(verify_toe_reflection_fixed cases/verification/toe-reflection-fixed.yaml verification)
pilempm_case_test(verify_energy_conservation cases/verification/energy-conservation.yaml verification)
pilempm_case_test(verify_axisymmetric_vs_rod cases/verification/axisymmetric-vs-rod.yaml verification)
pilempm_case_test(verify_mesh_convergence cases/verification/mesh-convergence.yaml verification)
# The default case runs in CI too, as a smoke test of every writer (VTK, HDF5, CSV, plots).
pilempm_case_test(north_sea_monopile_rod cases/pile-wave/north-sea-monopile.yaml validation)
pilempm_case_test(north_sea_monopile_ram_cushion cases/pile-wave/north-sea-monopile-ram-cushion.yaml validation)
pilempm_case_test(north_sea_monopile_axisymmetric cases/pile-wave/north-sea-monopile-axisymmetric.yaml validation)
# Wave-equation drivability (issue 3, checks 1-4) and the seed 001 study.
pilempm_case_test(verify_drivability_checks cases/verification/drivability-checks.yaml verification)
pilempm_case_test(north_sea_monopile_drivability cases/drivability/north-sea-monopile.yaml validation)
pilempm_case_test(example_cpt_sand_over_clay cases/drivability/cpt-sand-over-clay.yaml validation)
# MPM soil core (issue 4).
pilempm_case_test(verify_mpm_column_plane_strain cases/verification/mpm-column-plane-strain.yaml verification)
pilempm_case_test(verify_mpm_column_axisymmetric cases/verification/mpm-column-axisymmetric.yaml verification)
pilempm_case_test(verify_mpm_column_graded cases/verification/mpm-column-graded.yaml verification)
pilempm_case_test(verify_mpm_column_3d cases/verification/mpm-column-3d.yaml verification)
pilempm_case_test(verify_mpm_lame_cylinder cases/verification/mpm-lame-cylinder.yaml verification)
pilempm_case_test(verify_mpm_wave_1d cases/verification/mpm-wave-1d.yaml verification)
pilempm_case_test(verify_mpm_shear_wave_1d cases/verification/mpm-shear-wave-1d.yaml verification)
pilempm_case_test(verify_mpm_stress_noise_gimp cases/verification/mpm-stress-noise-gimp.yaml verification)
pilempm_case_test(verify_mpm_stress_noise_cpdi cases/verification/mpm-stress-noise-cpdi.yaml verification)
pilempm_case_test(verify_mpm_k0_initial_stress cases/verification/mpm-k0-initial-stress.yaml verification)
pilempm_case_test(verify_mpm_k0_surcharge cases/verification/mpm-k0-surcharge.yaml verification)
pilempm_case_test(verify_mpm_strip_footing cases/verification/mpm-strip-footing.yaml verification)
pilempm_case_test(verify_mpm_lame_cylinder_incompressible cases/verification/mpm-lame-cylinder-incompressible.yaml verification)
pilempm_case_test(verify_mpm_k0_cam_clay cases/verification/mpm-k0-cam-clay.yaml verification)
pilempm_case_test(verify_mpm_k0_subloading_cam_clay cases/verification/mpm-k0-subloading-cam-clay.yaml verification)
# Soil constitutive models in element tests (issue 5).
pilempm_case_test(verify_element_test_modified_cam_clay cases/element-tests/modified-cam-clay-fontainebleau.yaml verification)
pilempm_case_test(verify_element_test_hypoplastic cases/element-tests/hypoplastic-schlabendorfer.yaml verification)
pilempm_case_test(verify_mpm_k0_hypoplastic cases/verification/mpm-k0-hypoplastic.yaml verification)
pilempm_case_test(verify_element_test_subloading_cam_clay cases/element-tests/subloading-cam-clay-fontainebleau.yaml verification)
pilempm_case_test(verify_element_test_subloading_cam_clay_ocr4 cases/element-tests/subloading-cam-clay-fontainebleau-ocr4.yaml verification)
pilempm_case_test(verify_element_test_subloading_cam_clay_peak_cone cases/element-tests/subloading-cam-clay-fontainebleau-ocr4-peak-cone.yaml verification)
pilempm_case_test(verify_element_test_hardening_soil_small cases/element-tests/hardening-soil-small-north-sea-dense-sand.yaml verification)
pilempm_case_test(verify_mpm_k0_hardening_soil_small cases/verification/mpm-k0-hardening-soil-small.yaml verification)
# Saturated soil, explicit v-w (issue 12): Terzaghi, the undrained and the fast P-wave,
# absorbing boundaries for both phases, hydrostatic equilibrium under 40 m of water, Skempton's B.
pilempm_case_test(verify_terzaghi_explicit cases/verification/terzaghi-explicit.yaml verification)
pilempm_case_test(verify_terzaghi_implicit cases/verification/terzaghi-implicit.yaml verification)
pilempm_case_test(verify_terzaghi_double_drainage_implicit cases/verification/terzaghi-double-drainage-implicit.yaml verification)
pilempm_case_test(verify_saturated_wave_undrained cases/verification/saturated-wave-undrained.yaml verification)
pilempm_case_test(verify_saturated_wave_fast cases/verification/saturated-wave-fast.yaml verification)
pilempm_case_test(verify_saturated_wave_history_high_k cases/verification/saturated-wave-history-high-k.yaml verification)
pilempm_case_test(verify_saturated_wave_history_low_k cases/verification/saturated-wave-history-low-k.yaml verification)
pilempm_case_test(verify_hydrostatic_seabed cases/verification/hydrostatic-seabed.yaml verification)
pilempm_case_test(verify_skempton_b cases/verification/skempton-b.yaml verification)
pilempm_case_test(verify_skempton_b_compressible cases/verification/skempton-b-compressible.yaml verification)
# The FE pile in the soil (issue 13): the steel is impermeable to the pore water.
pilempm_case_test(verify_terzaghi_under_pile cases/verification/terzaghi-under-pile.yaml verification)
# A hammer blow on the coupled pile (issue 14): the half-sine's energy into the head.
pilempm_case_test(verify_coupled_blow_energy cases/verification/coupled-blow-energy.yaml verification)
pilempm_case_test(verify_coupled_ram_blow_energy cases/verification/coupled-ram-blow-energy.yaml verification)
pilempm_case_test(verify_coupled_driving_energy cases/verification/coupled-driving-energy.yaml verification)
pilempm_case_test(verify_coupled_ringing_pile cases/verification/coupled-ringing-pile.yaml verification)
# Validation 3 (issue 13): seed 002's shaft capacity, jacked over wished in place, against
# the paper's trends: the six models of Table 2 at the paper's D/4, and the short piles
# (models 1 and 2) on a grid sequence that must converge. Hours each: label long.
function(pilempm_shaft_capacity_test name cells models label)
  add_test(NAME ${name}
    COMMAND python3 ${PROJECT_SOURCE_DIR}/scripts/shaft_capacity_study.py --cells-per-diameter ${cells}
            --models ${models} --check --threads 1 --pilempm $<TARGET_FILE:pilempm>
            --out ${CMAKE_BINARY_DIR}/test-output/${name})
  set_tests_properties(${name} PROPERTIES LABELS ${label} TIMEOUT 36000)
endfunction()
# In CI, models 1 and 2 on D/3 (about 5 min on one thread): phi' 40 must gain more than
# phi' 20 and both more than 1 (1.77 and 1.57 measured, the stress bounded by each sand's cone).
pilempm_shaft_capacity_test(validation_shaft_capacity_reduced 3 1,2 validation)
pilempm_shaft_capacity_test(long_shaft_capacity 4 1,2,3,4,5,6 long)
pilempm_shaft_capacity_test(long_shaft_capacity_sequence 4,6,8 1,2 long)
# Validation 1 (issue 13): the mini-ICP of seed 002 at the paper's resolution (44 756 points;
# some 2 h 20 min on two threads), against the paper's findings and ICP-05
# (compare_mini_icp.py --check): label long.
add_test(NAME long_mini_icp
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:pilempm> -DCASE=${PROJECT_SOURCE_DIR}/cases/jacking/mini-icp.yaml
          -DSCRIPT=${PROJECT_SOURCE_DIR}/scripts/compare_mini_icp.py -DARGS=--check
          -DOUT=${CMAKE_BINARY_DIR}/test-output/long_mini_icp -P ${CMAKE_CURRENT_SOURCE_DIR}/run_case_then_script.cmake)
set_tests_properties(long_mini_icp PROPERTIES LABELS long TIMEOUT 36000)
# Validation 2 (issue 13): seed 000's centrifuge pile (Huy 2008) jacked at 40 g and
# load-tested, with and without installation, against NEN 9997-1's base settlement lines and
# the seed's trends. CI: Mohr-Coulomb in medium-dense sand on cells of D/2 in a cut
# container; long: both sands and both models on D/4 in the whole container.
function(pilempm_centrifuge_test name cells container sands models label)
  add_test(NAME ${name}
    COMMAND python3 ${PROJECT_SOURCE_DIR}/scripts/centrifuge_study.py --cells-per-diameter ${cells}
            --container ${container} --sands ${sands} --models ${models}
            --check --threads 1 --pilempm $<TARGET_FILE:pilempm> --out ${CMAKE_BINARY_DIR}/test-output/${name})
  set_tests_properties(${name} PROPERTIES LABELS ${label} TIMEOUT 72000)
endfunction()
pilempm_centrifuge_test(validate_centrifuge_huy2008 2 cut medium mohr_coulomb validation)
pilempm_centrifuge_test(long_centrifuge_huy2008 4 full medium,loose mohr_coulomb,hypoplastic long)
# Case 3 of issue 14 (seed 000 D): the rapid load test by the unloading-point method against
# the static load test of the same model, at the seed's permeability and 100 times it and
# drained; the trends of load_test_study.py --check (some 5 min on one thread): long.
add_test(NAME long_rapid_load_test_study
  COMMAND python3 ${PROJECT_SOURCE_DIR}/scripts/load_test_study.py --permeabilities 2e-5,2e-3
          --check --threads 1 --pilempm $<TARGET_FILE:pilempm> --out ${CMAKE_BINARY_DIR}/test-output/long_rapid_load_test_study)
set_tests_properties(long_rapid_load_test_study PROPERTIES LABELS long TIMEOUT 7200)
# Full-size runs (label long, not in CI: ctest --test-dir build -L long).
# Granular column collapse, Mohr-Coulomb: the final height against Lube et al. on grid
# sequences of three (11-17 min each on one core).
pilempm_case_test(long_collapse_plane_strain_a05 cases/examples/column-collapse-plane-strain-a05.yaml long)
pilempm_case_test(long_collapse_axisymmetric_a05 cases/examples/column-collapse-axisymmetric-a05.yaml long)
pilempm_case_test(long_collapse_plane_strain_a2 cases/examples/column-collapse-plane-strain-a2.yaml long)
pilempm_case_test(long_collapse_axisymmetric_a2 cases/examples/column-collapse-axisymmetric-a2.yaml long)
# The energy-levels drivability study with its bearing graph.
pilempm_case_test(long_drivability_energy_levels cases/drivability/north-sea-monopile-energy-levels.yaml long)
# Fast path against field records (issue 15): the full ISFOG 2020 study (38 locations,
# against the issue's aims) and a three-location version in CI.
pilempm_case_test(long_isfog2020_study cases/drivability/isfog2020-study.yaml long)
pilempm_case_test(validate_isfog2020_three_locations cases/drivability/isfog2020-study-three-locations.yaml validation)
# Coupling verification 2 (issue 13): the rigid circular punch on an elastic half-space on
# two graded grids (a/4, a/8; about 9 min on two threads, 16 on one): long.
pilempm_case_test(long_rigid_punch cases/verification/rigid-punch.yaml long)
# Issue 14: the North Sea monopile's first 30 blows in the coupled model (shipped case,
# reduced size; some 14 min on two threads): every blow's ENTHRU within 2 % of
# F0^2 t_i / (2 Z) (measured +0.09 to +0.53 % over 30 blows), and the ledger: the steel's
# energy below ENTHRU plus the weight's work since the blow began (measured 1.9 % below).
add_test(NAME long_north_sea_drive_energy
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:pilempm>
          -DCASE=${PROJECT_SOURCE_DIR}/cases/driving/north-sea-monopile.yaml
          "-DEDITS=blows: 2000=>blows: 30"
          -DAPPEND=${CMAKE_CURRENT_SOURCE_DIR}/verification/north-sea-drive-energy.yaml
          -DOUT=${CMAKE_BINARY_DIR}/test-output/long_north_sea_drive_energy
          -P ${CMAKE_CURRENT_SOURCE_DIR}/run_verification_case.cmake)
set_tests_properties(long_north_sea_drive_energy PROPERTIES LABELS long TIMEOUT 7200)
# Issue 14: the fast path calibrated by the coupled model (three coupled runs shipped as
# data; some 5 s): each fitted set within 40 % of the coupled model's.
pilempm_case_test(north_sea_calibrated_fast_path_coarse cases/drivability/north-sea-monopile-calibrated-0.5m-grid.yaml validation)
# The same fitted to the installed coupled drive (5 blows at each of 6, 8, 10, 11.5 m of its
# 787 from 4.8 to 12 m; some 15 s): the calibrated sheet's blows over the drive's depths
# within 15 % of the drive's (measured -6.8 %), each fitted set within 60 % (the dense
# layer's +54 %, the others within 21 %).
pilempm_case_test(north_sea_calibrated_to_drive cases/drivability/north-sea-monopile-calibrated-to-drive.yaml validation)
# The same fitted to two coupled runs on 0.125 m cells (5 and 8 m): each fitted set within 10 %.
pilempm_case_test(north_sea_calibrated_fast_path_fine cases/drivability/north-sea-monopile-calibrated.yaml validation)
