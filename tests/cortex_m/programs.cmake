# The programs of tests/cortex_m/, one per chart and implementation (<chart>_<implementation>.cpp):
# built for the host by tests/cortex_m.cmake and for the Cortex-M4 by tests/cortex_m/CMakeLists.txt.
# *_floor is each chart's driver with a subject that does nothing, which the report measures the
# others' flash and instructions from (scripts/cortex_m.py). cd_player: bench/sml_simple's chart;
# mcs: examples/mcs; cell: examples/manufacturing_cell's controller. bsc: the default policy
# (cell: bsc::scan_policy, as the example's machine); lean: bsc::lean_policy; hand: written by hand.
set(BSC_CORTEX_M_PROGRAMS
  cd_player_floor cd_player_hand cd_player_bsc cd_player_lean
  mcs_floor mcs_hand mcs_bsc mcs_lean
  cell_floor cell_hand cell_bsc)
