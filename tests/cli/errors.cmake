# Command-line tests: one test per error message (exit code 1, exactly one line on stderr that
# names the file, the parameter and the problem), and the commands that must succeed.
# Bad inputs live in tests/cli/inputs/: each bad_*.xml is base.xml with one thing changed.
# The table of messages is in README.md, "Input errors".
set(CLI_INPUTS ${CMAKE_CURRENT_LIST_DIR}/inputs)
set(CLI_SCRIPTS ${CMAKE_CURRENT_LIST_DIR}/scripts)
set(CLI_WORK ${CMAKE_CURRENT_BINARY_DIR}/work)

# choc_cli_test(<name> RC <code> [STDERR <regex>] [ONE_LINE] [STDOUT <regex>...] ARGS <args>...)
# Regexes may not contain ";" (the list separator) nor an unbalanced "[" or "]" (CMake does not
# split lists inside brackets): match those characters with ".".
function(choc_cli_test name)
  cmake_parse_arguments(T "ONE_LINE" "RC;STDERR" "STDOUT;ARGS" ${ARGN})
  string(REPLACE ";" "@@" args "${T_ARGS}")
  string(REPLACE ";" "@@" outre "${T_STDOUT}")
  set(one 0)
  if(T_ONE_LINE)
    set(one 1)
  endif()
  add_test(NAME cli.${name}
           COMMAND ${CMAKE_COMMAND} -DCHOC=$<TARGET_FILE:choc> "-DARGS=${args}" -DRC=${T_RC}
                   "-DSTDERR_REGEX=${T_STDERR}" -DONE_LINE=${one} "-DSTDOUT_REGEX=${outre}"
                   -DWORKDIR=${CLI_WORK}/${name} -P ${CLI_SCRIPTS}/expect.cmake)
  set_tests_properties(cli.${name} PROPERTIES TIMEOUT 60 LABELS cli)
endfunction()

# An input error from `choc <command> <input>`: "choc: input error: <path to input>: <tail>".
function(choc_cli_input_error name command input tail)
  choc_cli_test(error.${name} RC 1 ONE_LINE
                STDERR "^choc: input error: .*${input}: ${tail}"
                ARGS ${command} ${CLI_INPUTS}/${input})
endfunction()

# A command-line error: "choc: input error: <tail>" for `choc <args...>`.
function(choc_cli_command_error name tail)
  choc_cli_test(error.${name} RC 1 ONE_LINE STDERR "^choc: input error: ${tail}" ARGS ${ARGN})
endfunction()

# --- the input file itself --------------------------------------------------------------
choc_cli_input_error(missing_input_file run no_such_input.xml
  "input file not found. check the path")
choc_cli_test(error.input_is_directory RC 1 ONE_LINE
  STDERR "^choc: input error: .*inputs: is a directory, not an input file"
  ARGS check ${CLI_INPUTS})
choc_cli_input_error(empty_file check bad_empty.xml
  "input file is empty. it must hold a <ParameterList>")
choc_cli_input_error(malformed_xml check bad_malformed.xml
  "malformed XML: XML parse error at line 6: file ended before closing element 'ParameterList' from line 1. fix the XML")
choc_cli_input_error(not_a_parameter_list check bad_not_parameterlist.xml
  "malformed XML parameter list: XMLParameterListReader expected tag ParameterList, found html")

# --- keys, types, values ----------------------------------------------------------------
choc_cli_input_error(unknown_key_top_level check bad_unknown_top_key.xml
  "parameter 'Meshes': unknown parameter. did you mean 'Mesh'\\?")
choc_cli_input_error(unknown_key_in_sublist check bad_unknown_sub_key.xml
  "parameter 'Model/Materials/steel/Densty': unknown parameter. did you mean 'Density'\\?")
choc_cli_input_error(duplicate_key check bad_duplicate_key.xml
  "parameter 'Model/Materials/steel/Density': is given twice in the same list. keep only one")
choc_cli_input_error(parameter_instead_of_sublist check bad_parameter_not_sublist.xml
  "parameter 'Mesh' = '[^']*sdnl111_1d.exo': must be a sublist \\(<ParameterList name=\"Mesh\">\\)")
choc_cli_input_error(wrong_type_string_for_double check bad_wrong_type.xml
  "parameter 'Model/Materials/steel/Density' = 'heavy': has type string, expected double. write type=\"double\"")
choc_cli_input_error(wrong_type_double_for_int check bad_int_type.xml
  "parameter 'Analyses/modes/Number of Modes' = '5.5': has type double, expected int. write type=\"int\"")
choc_cli_input_error(not_a_number check bad_double_value.xml
  "parameter 'Model/Materials/steel/Density' = '7800kg': is not a number")
choc_cli_input_error(not_a_bool check bad_bool_value.xml
  "parameter 'Analyses/modes/Write Exodus' = 'nope': is not a bool. write true or false")
choc_cli_input_error(unknown_xml_type check bad_unknown_type.xml
  "parameter 'Model/Materials/steel/Density': unknown type 'duble'. use type=")
choc_cli_input_error(negative_density check bad_negative_density.xml
  "parameter 'Model/Materials/steel/Density' = '-7800': out of range. valid: a number in \\(0, inf.")
choc_cli_input_error(zero_youngs_modulus check bad_zero_young.xml
  "parameter 'Model/Materials/steel/Young's Modulus' = '0': out of range. valid: a number in \\(0, inf.")
choc_cli_input_error(poisson_ratio_one_half check bad_poisson_half.xml
  "parameter 'Model/Materials/steel/Poisson's Ratio' = '0.5': out of range. valid: a number in \\(-1, 0.5\\)")
choc_cli_input_error(negative_section_side check bad_negative_section.xml
  "parameter 'Model/Blocks/POU1/Section/Square Side' = '-0.02': out of range. valid: a number in .0, inf.")
choc_cli_input_error(zero_section check bad_zero_section.xml
  "parameter 'Model/Blocks/POU1/Section/Area' = '0': a beam block needs a positive value. set 'Square Side' or all of Area")
choc_cli_input_error(missing_required_key check bad_missing_mesh_file.xml
  "parameter 'Mesh/File': is required but missing. add it")
choc_cli_input_error(no_analysis check bad_no_analysis.xml
  "parameter 'Analyses': no analysis to run. add at least one sublist with a Type")
choc_cli_input_error(unknown_analysis_type check bad_unknown_analysis_type.xml
  "parameter 'Analyses/modes/Type' = 'Modale': unknown analysis type. did you mean 'Modal'\\? valid: ")
choc_cli_input_error(invalid_choice check bad_choice.xml
  "parameter 'Analyses/modes/Which' = 'lowest': is not a valid choice. did you mean 'Lowest'\\? valid: one of 'Lowest', 'Nearest Shift'")

# --- the input against the mesh ----------------------------------------------------------
choc_cli_input_error(mesh_file_missing check bad_mesh_missing.xml
  "parameter 'Mesh/File' = 'no_such_mesh.exo': cannot use the mesh: [^ ]*no_such_mesh.exo: mesh file not found")
choc_cli_input_error(mesh_file_not_exodus check bad_mesh_not_exodus.xml
  "parameter 'Mesh/File' = 'not_exodus.txt': cannot use the mesh: [^ ]*not_exodus.txt: not a readable Exodus II file")
# A header whose counts do not fit the file is refused before netCDF allocates what they declare.
choc_cli_input_error(mesh_file_corrupt_header check bad_mesh_corrupt_header.xml
  "parameter 'Mesh/File' = 'corrupt_header.exo': cannot use the mesh: [^ ]*corrupt_header.exo: corrupt netCDF header at byte 156: the name of dimension 3 is 1853189471 bytes long \\(netCDF names have 1 to 256\\). check that the file is a complete Exodus II mesh")
# A netCDF-4 mesh on which Debian's HDF5 segfaults (found by fuzzing): read in a child process.
choc_cli_input_error(mesh_file_corrupt_hdf5 check bad_mesh_corrupt_hdf5.xml
  "parameter 'Mesh/File' = 'corrupt_hdf5.exo': cannot use the mesh: [^ ]*corrupt_hdf5.exo: the HDF5 library crashed \\(signal 11, Segmentation fault\\) reading this file: it is corrupt. check that the file is a complete Exodus II mesh")
choc_cli_input_error(mesh_file_truncated check bad_mesh_truncated.xml
  "parameter 'Mesh/File' = 'truncated.exo': cannot use the mesh: [^ ]*truncated.exo: data past the end of the file \\(truncated\\?\\): variable 'time_whole' starts at byte 6092 but the file has 2000 bytes")
choc_cli_input_error(node_set_not_in_mesh check bad_nodeset_unknown.xml
  "parameter 'Model/Dirichlet/clamped end D/Node Set' = 'DD': no node set of that name in the mesh. did you mean 'D'\\? node sets: A, B, C, D, POU1, POU2")
choc_cli_input_error(block_not_in_mesh check bad_block_unknown.xml
  "parameter 'Model/Blocks/BAR3': no element block of that name in the mesh. blocks: POU1, POU2")
choc_cli_input_error(mesh_block_without_entry check bad_block_missing.xml
  "parameter 'Model/Blocks': mesh block 'POU2' has no entry. add <ParameterList name=\"POU2\">")
choc_cli_input_error(material_not_defined check bad_material_unknown.xml
  "parameter 'Model/Blocks/POU1/Material' = 'stel': no material of that name. did you mean 'steel'\\?")
choc_cli_input_error(bad_component_name check bad_component.xml
  "parameter 'Model/Dirichlet/clamped end D/Components' = 'DQ': unknown component 'DQ' \\(valid: DX, DY, DZ")
choc_cli_input_error(bad_active_component check bad_active_component.xml
  "parameter 'Model/Active Components' = 'DX DW': unknown component 'DW'")
choc_cli_input_error(no_unknowns check bad_no_unknowns.xml
  "parameter 'Model/Active Components' = 'DX': the model has no unknowns")

# Meshes of other tools (gmsh .msh, Exodus): bad elements and groups, one line each.
choc_cli_input_error(mesh_inverted_element check bad_mesh_inverted.xml
  "parameter 'Mesh/File' = 'inverted_tet.msh': block 'body', element 2: inverted or degenerate TET4 element: Jacobian determinant -2 <= 0")
choc_cli_input_error(mesh_unsupported_element check bad_mesh_prism.xml
  "parameter 'Mesh/File' = 'prism.msh': cannot use the mesh: .*prism.msh: physical group 'body' has elements of type 'Prism 6' .gmsh type 6., which choc does not support")
choc_cli_input_error(mesh_2d_for_3d_model check bad_mesh_2d_for_3d.xml
  "parameter 'Model/Kinematics' = '3D': block 'plate' has TRI3 elements .a 2D mesh.. set 'Kinematics' to 'plane strain' or 'axisymmetric'")
choc_cli_input_error(mesh_groups_of_mixed_dimension check bad_mesh_mixed_dimension.xml
  "parameter 'Mesh/File' = 'mixed_dimension.msh': cannot use the mesh: .*mixed_dimension.msh: physical group 'body' is defined in dimensions 2 and 3 .mixed dimension.")
choc_cli_input_error(mesh_side_not_of_an_element check bad_mesh_not_a_face.xml
  "parameter 'Mesh/File' = 'not_a_face.msh': cannot use the mesh: .*not_a_face.msh: physical group 'top': element 2 is not a side of any element of the blocks")

# --- references resolved by the analyses' setup: `choc check` gives the line `choc run` gives,
# and the run writes no result (setup comes before any analysis runs) ----------------------
function(choc_cli_reference_error name input tail)
  add_test(NAME cli.error.${name}
           COMMAND ${CMAKE_COMMAND} -DCHOC=$<TARGET_FILE:choc> -DINPUT=${CLI_INPUTS}/${input}
                   "-DSTDERR_REGEX=^choc: input error: .*${input}: ${tail}"
                   -DWORKDIR=${CLI_WORK}/${name} -P ${CLI_SCRIPTS}/check_equals_run.cmake)
  set_tests_properties(cli.error.${name} PROPERTIES TIMEOUT 120 LABELS cli)
endfunction()
# 101 unknowns, at most 99 modes.
choc_cli_reference_error(too_many_modes bad_too_many_modes.xml
  "parameter 'Analyses/modes/Number of Modes' = '100': more modes than the model's 101 unknowns allow. ask for at most 99")
choc_cli_reference_error(history_node_set_not_in_mesh bad_history_node_set.xml
  "parameter 'Analyses/shock/History' = 'AA': no node set of that name in the mesh. did you mean 'A'. node sets: A, B, C, D, POU1, POU2")
choc_cli_reference_error(modal_basis_not_computed bad_modal_basis.xml
  "parameter 'Analyses/shock/Modal Basis' = 'mode': no modal basis of that name has been computed. did you mean 'modes'. name a Modal analysis listed before this one in Analyses .listed before: modes.")
choc_cli_reference_error(contact_side_set_not_in_mesh bad_contact_side_set.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface/Master Side Set' = 'CNT_POU3': no side set of that name in the mesh. did you mean 'CNT_POU1'. side sets: ")
choc_cli_reference_error(contact_same_surface bad_contact_same_surface.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface/Master Side Set' = 'CNT_POU2': master and slave are the same surface. pair two different side sets")
choc_cli_reference_error(contact_without_master bad_contact_no_master.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface': the pair has neither a 'Master Side Set' nor an 'Obstacle'. name the master side set, or give 'Obstacle/Shape'")
choc_cli_reference_error(contact_beyond_search_distance bad_contact_search_distance.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface/Search Distance' = '1e-06': contact pair 'interface': no node of slave side set 'CNT_POU2' projects onto a face of master side set 'CNT_POU1' within the search distance 0.000001 m. check the side set names, or raise 'Search Distance' above the initial gaps")
choc_cli_reference_error(contact_mortar_quadratic_slave bad_contact_mortar_quadratic.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface/Discretization' = 'mortar': slave side set 'CNT_POU2' has TRI6 faces: mortar takes TRI3, QUAD4 and LINE2 slave faces. make a surface of linear faces the slave, or use 'node to face'")
choc_cli_input_error(contact_mortar_obstacle check bad_contact_mortar_obstacle.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface/Discretization' = 'mortar': mortar pairs a slave side set with a master side set, not with an obstacle or a node set. give a 'Master Side Set', or leave 'Discretization' = node to face")
choc_cli_reference_error(obstacle_zero_normal bad_obstacle_zero_normal.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface/Obstacle/Normal' = '0 0 0': the plane's normal is zero. give a non-zero direction 'x y z'")
choc_cli_reference_error(obstacle_zero_radius bad_obstacle_zero_radius.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface/Obstacle/Radius' = '0': the sphere's radius must be > 0. give the radius \\[m\\]")
choc_cli_reference_error(cg_with_contact_multipliers bad_cg_multiplier.xml
  "parameter 'Analyses/impact/Linear Solver/Method' = 'CG': the saddle-point system of contact method 'Continuous' between meshed bodies is indefinite. use Direct, GMRES or MINRES")
# Multigrid for elasticity aggregates nodal unknowns: a Newton matrix with multiplier rows
# (Continuous contact between meshed bodies; Lagrange's are condensed out against obstacles and
# projected out between meshed bodies) is refused.
choc_cli_input_error(multigrid_with_contact_multipliers check bad_multigrid_multiplier.xml
  "parameter 'Analyses/impact/Linear Solver/Preconditioner' = 'Multigrid': the Newton matrix of contact method 'Continuous' between meshed bodies has multiplier rows, which multigrid for elasticity does not aggregate. use the Penalty method with Multigrid, or Method = Direct or auto")
# ... but central differences make no linear solve: the same input by them is valid.
choc_cli_test(explicit_lagrange_with_cg RC 0 STDOUT "explicit_lagrange_cg.xml is valid"
              ARGS check ${CLI_INPUTS}/explicit_lagrange_cg.xml)
# ... and so is multigrid stated with them (no Newton matrix to aggregate).
choc_cli_test(explicit_lagrange_with_multigrid RC 0 STDOUT "explicit_lagrange_multigrid.xml is valid"
              ARGS check ${CLI_INPUTS}/explicit_lagrange_multigrid.xml)

# --- the command line -------------------------------------------------------------------
choc_cli_command_error(mesh_zero_length
  "choc mesh: parameter '--length1' = '0': must be a finite number > 0" mesh --length1 0 -o m.exo)
choc_cli_command_error(mesh_negative_length
  "choc mesh: parameter '--length2' = '-1': must be a finite number > 0" mesh --length2 -1 -o m.exo)
choc_cli_command_error(mesh_zero_width
  "choc mesh: parameter '--width' = '0': must be a finite number > 0" mesh --dim 3 --width 0 -o m.exo)
choc_cli_command_error(mesh_zero_elements
  "choc mesh: parameter '--along1' = '0': must be an integer >= 1" mesh --along1 0 -o m.exo)
choc_cli_command_error(mesh_bad_axis
  "choc mesh: parameter '--axis' = 'w': must be x, y or z" mesh --axis w -o m.exo)
choc_cli_command_error(mesh_bad_dimension
  "choc mesh: parameter '--dim' = '2': must be 1 or 3" mesh --dim 2 -o m.exo)
choc_cli_command_error(mesh_not_a_number
  "choc mesh: parameter '--length1' = 'abc': is not a number" mesh --length1 abc -o m.exo)
choc_cli_command_error(mesh_unknown_option
  "choc mesh: parameter '--lenght1': unknown option. run 'choc mesh --help'" mesh --lenght1 1 -o m.exo)
choc_cli_command_error(mesh_option_without_value
  "choc mesh: parameter '--along1': needs a value" mesh --along1)
choc_cli_command_error(mesh_no_output
  "choc mesh: parameter '-o': no output file given. add -o FILE.exo" mesh --dim 3)
choc_cli_command_error(unknown_command
  "unknown command 'frobnicate'. valid: run, check, parameters, mesh, --help" frobnicate)
choc_cli_command_error(run_without_input
  "choc run: missing INPUT.xml \\(usage: choc run INPUT.xml\\)" run)
choc_cli_command_error(check_without_input
  "choc check: missing INPUT.xml" check)
choc_cli_command_error(run_two_inputs
  "choc run: one input file expected, got 'a.xml' and 'b.xml'" run a.xml b.xml)
choc_cli_command_error(run_unknown_option
  "choc run: unknown option '-x'. valid: -o DIR" run -x)
choc_cli_command_error(run_output_option_without_directory
  "choc run: option -o needs a directory" run ${CLI_INPUTS}/base.xml -o)
choc_cli_command_error(parameters_with_argument
  "choc parameters: takes no argument \\(got 'extra'\\)" parameters extra)
# No command at all: the usage text on stderr (several lines) and exit code 1.
choc_cli_test(no_command RC 1 STDERR "^usage: choc <command>")

# --- what must succeed ----------------------------------------------------------------
# The base of every bad_*.xml is valid: each bad input fails for its one change only.
choc_cli_test(check_base_input RC 0 STDOUT "base.xml is valid: 102 nodes, 101 unknowns"
              ARGS check ${CLI_INPUTS}/base.xml)
choc_cli_test(check_sdnl111a RC 0
              STDOUT "sdnl111a.xml is valid: 102 nodes, 101 unknowns"
                     "Mass : string = consistent"
                     "Shear Coefficient : double = 0.833333"
                     "Residual Tolerance : double = 1e-06"
                     "Direct Package : string = KLU2"
              ARGS check ${CMAKE_SOURCE_DIR}/input/sdnl111a.xml)
# Keys of the previous release still work, translated, with one deprecation warning each.
choc_cli_test(deprecated_keys RC 0
              STDOUT "parameter 'Analyses/impact/Write Exodus' is deprecated .*use 'Exodus Interval'"
                     "parameter 'Analyses/impact/Log Interval' is deprecated"
                     "parameter 'Analyses/impact/Exact Solution' is deprecated"
                     "parameter 'Analyses/shock/Progress Lines' is deprecated"
                     "Exodus Interval : int = 0"
                     "Type : string = Bar Impact Exact Solution"
                     "Progress Interval : double = 0"
              ARGS check ${CLI_INPUTS}/deprecated_keys.xml)
choc_cli_test(parameters RC 0
              STDOUT "Young's Modulus \\(double, default 0. a number in \\(0, inf.\\)"
                     "Density \\(double, required"
                     "Mass \\(string, default 'consistent'. one of 'consistent', 'lumped'\\)"
                     "Node Set \\(string, required"
                     "Number of Modes \\(int, default 10"
                     "Analyses/<name> with Type = 'Modal'"
                     "Checks/<name> with Type = 'Bar Impact Exact Solution'"
                     "Progress Interval \\(double, default 10"
              ARGS parameters)
add_test(NAME cli.parameters_documented
         COMMAND sh ${CLI_SCRIPTS}/parameters_documented.sh $<TARGET_FILE:choc>
                 ${CMAKE_SOURCE_DIR}/input/sdnl111a.xml ${CLI_INPUTS}/base.xml)
choc_cli_test(help RC 0 STDOUT "usage: choc <command>" "exit codes: 0 success, 1 input error"
              ARGS --help)
choc_cli_test(mesh_help RC 0 STDOUT "usage: choc mesh" ARGS mesh --help)
add_test(NAME cli.modal_sdnl111a
         COMMAND sh ${CLI_SCRIPTS}/modal_run.sh $<TARGET_FILE:choc>
                 ${CMAKE_SOURCE_DIR}/input/sdnl111a.xml ${CLI_WORK}/modal_sdnl111a)
set_tests_properties(cli.parameters_documented cli.modal_sdnl111a PROPERTIES TIMEOUT 120 LABELS cli)

# Contact on nodes without faces (beam structures against an obstacle).
choc_cli_reference_error(contact_slave_side_and_node_set bad_contact_slave_both.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface/Slave Side Set' = 'CNT_POU2': the pair also has a 'Slave Node Set'. give either 'Slave Side Set' or \\(against an 'Obstacle'\\) 'Slave Node Set'")
choc_cli_reference_error(contact_node_set_with_master bad_contact_node_set_master.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface/Slave Node Set' = 'FACE_POU2': a slave node set has no faces to pair with a master side set. give an 'Obstacle', or a 'Slave Side Set'")
choc_cli_reference_error(contact_node_set_missing bad_contact_node_set_missing.xml
  "parameter 'Analyses/impact/Contact/Pairs/interface/Slave Node Set' = 'TIP': no node set of that name in the mesh. node sets: POU1, POU2, N1, A, B, C, D, CL_POU2, FACE_POU1, FACE_POU2")
# A shock link of a direct transient with the modal transient's rigid law.
choc_cli_reference_error(link_rigid_direct bad_link_rigid_direct.xml
  "parameter 'Analyses/impact/Shock Links/shock/Normal Law' = 'rigid': is the modal transient's forward-increment constraint, not available in a direct transient. use 'penalty' with a stiffness, or a contact pair with the Lagrange method")
# Shock-link friction: a rigid link with friction, a negative Coulomb coefficient, a
# negative stick stiffness.
choc_cli_input_error(link_rigid_friction check bad_link_rigid_friction.xml
  "parameter 'Analyses/shock/Shock Links/link/Normal Law' = 'rigid': carries no tangential force .the link has a tangential stiffness, damping or friction.. use the penalty law for a link with friction")
choc_cli_input_error(link_negative_friction check bad_link_negative_friction.xml
  "parameter 'Analyses/shock/Shock Links/link/Friction Coefficient' = '-0.1': out of range. valid: a number in .0, inf.")
choc_cli_input_error(link_negative_stick check bad_link_negative_stick.xml
  "parameter 'Analyses/shock/Shock Links/link/Tangential Stiffness' = '-400000': out of range. valid: a number in .0, inf.")
# A fixed obstacle's origin on a link between two nodes (SDNV100 (f)).
choc_cli_input_error(link_origin_with_node2 check bad_link_origin_with_node2.xml
  "parameter 'Analyses/shock/Shock Links/link/Obstacle Origin' = '0 0 -0.002': places a fixed obstacle, but 'Node 2' = 'C' is given. leave 'Node 2' empty for a fixed obstacle at this origin, or leave 'Obstacle Origin' empty")
# Explicit central differences: a consistent mass, pressure unknowns, a step above
# the stable one.
choc_cli_input_error(explicit_consistent_mass check bad_explicit_consistent_mass.xml
  "parameter 'Analyses/impact/Scheme' = 'central differences': needs a diagonal mass with every entry positive. set 'Mass' = 'lumped' in every block")
choc_cli_input_error(explicit_continuous check bad_explicit_continuous.xml
  "parameter 'Analyses/impact/Contact/Method' = 'Continuous': has pressure unknowns, which the explicit scheme .central differences. cannot solve for. use Lagrange .forward-increment multipliers. or Penalty with central differences")
choc_cli_input_error(explicit_time_step check bad_explicit_time_step.xml
  "parameter 'Analyses/impact/Time Step' = '1e-05': 1e-05 s exceeds the stable step of the explicit scheme, 3.9[0-9]*e-06 s .the critical step 3.9[0-9]*e-06 s.. the highest frequency is at most [0-9]+ rad/s")
# The direct transient's time grid starts at 'Start Time': an end time not after it is refused.
choc_cli_input_error(transient_start_after_end check bad_transient_start_after_end.xml
  "parameter 'Analyses/impact/End Time' = '1e-05': does not exceed the Start Time. use an end time after 'Start Time' = 2e-05")
# Contact friction: a negative Coulomb coefficient or stick stiffness, friction in an
# explicit run or with CG.
choc_cli_input_error(contact_negative_friction check bad_contact_negative_friction.xml
  "parameter 'Analyses/impact/Contact/Pairs/shock/Friction Coefficient' = '-0.3': out of range. valid: a number in .0, inf.")
choc_cli_input_error(contact_negative_tangential check bad_contact_negative_tangential.xml
  "parameter 'Analyses/impact/Contact/Tangential Stiffness' = '-1e.09': out of range. valid: a number in .0, inf.")
choc_cli_input_error(friction_explicit check bad_friction_explicit.xml
  "parameter 'Analyses/impact/Contact/Pairs/shock/Friction Coefficient' = '0.3': central differences apply friction by forward increments of Lagrange contact, not with 'Penalty' contact. use 'Contact/Method' = Lagrange, or an implicit scheme")
choc_cli_input_error(initial_rigid_components check bad_initial_rigid_components.xml
  "parameter 'Analyses/impact/Initial Conditions/bar 1/Components' = 'DX': is not used with Field = 'Rigid Velocity'. remove it")
choc_cli_input_error(rigid_implicit check bad_rigid_implicit.xml
  "parameter 'Model/Blocks/box/Rigid' = 'true': rigid blocks run in explicit transients only so far .issue 74., and Analyses/spin is implicit .'Scheme' = 'HHT'.. use a 'Transient' with 'Scheme' = 'central differences'")
choc_cli_input_error(rigid_modal check bad_rigid_modal.xml
  "parameter 'Model/Blocks/box/Rigid' = 'true': rigid blocks run in explicit transients only so far .issue 74., and Analyses/modes is a modal analysis")
choc_cli_input_error(rigid_fixed_node check bad_rigid_fixed_node.xml
  "parameter 'Model/Blocks/box/Rigid' = 'true': its node 1 has component X fixed or inactive")
choc_cli_input_error(rigid_held_not_rigid check bad_rigid_held_not_rigid.xml
  "parameter 'Model/Blocks/POU2/Held' = 'DZ': holds the motion of a rigid body, and the block is not rigid. set 'Rigid' = true")
choc_cli_input_error(rigid_held_rotation check bad_rigid_held_rotation.xml
  "parameter 'Model/Blocks/POU1/Held' = 'DZ DRX': a rigid body's rotations are held together .its angular velocity kept at 0.. give all of DRX DRY DRZ, or none")
choc_cli_input_error(rigid_held_velocity check bad_rigid_held_velocity.xml
  "parameter 'Model/Blocks/POU1/Held Velocity' = '0.5 0 -1': gives a speed along X, whose component is not held. add DX to 'Held', or give 0 there")
choc_cli_input_error(coupling_unknown check bad_coupling_unknown.xml
  "parameter 'Analyses/bend/Coupling Loads/end moment/Coupling' = 'tip': no entry of Model/Couplings of that name. name a coupling of Model/Couplings")
choc_cli_input_error(coupling_fixed_node check bad_coupling_fixed_node.xml
  "parameter 'Model/Couplings/end/Node Set' = 'CLAMPED': its node 1 has component X fixed or inactive .the load spread on it would go to the support.")
choc_cli_input_error(coupling_line check bad_coupling_line.xml
  "parameter 'Analyses/bend/Coupling Loads/end moment/Moment' = '0 0 16755.160819145563': coupling 'end': its nodes lie on one line: a moment cannot be spread over them")
choc_cli_input_error(gravity_2d check bad_gravity_2d.xml
  "parameter 'Analyses/lagrange/Gravity' = '0 0 -9.81': a 2D model moves in the x-y plane. give gravity with z = 0")
choc_cli_input_error(coupling_on_rigid check bad_coupling_on_rigid.xml
  "parameter 'Model/Couplings/face/Type' = 'kinematic': its node 1 is also a node of the body of Model/Blocks/POU1/Rigid .two bodies cannot share a node.")
choc_cli_input_error(rigid_explicit_friction check bad_rigid_explicit_friction.xml
  "parameter 'Analyses/strike/Contact/Method' = 'Lagrange': friction beside rigid blocks is not available in central differences so far .issue 74.. make the pairs frictionless")
choc_cli_input_error(initial_missing_components check bad_initial_missing_components.xml
  "parameter 'Analyses/impact/Initial Conditions/bar 1/Components': is required with Field = 'Velocity'. add it")
choc_cli_input_error(friction_cg check bad_friction_cg.xml
  "parameter 'Analyses/impact/Contact/Pairs/shock/Friction Coefficient' = '0.3': the tangent of a sliding node is not symmetric, which CG cannot solve. use 'Linear Solver/Method' = Direct or GMRES")
# Loads and springs (SDNV104): each bad input is input/sdnv104_quad4.xml with one thing
# changed: a pressure on a side set the mesh lacks, a negative ramp time; a spring on a missing
# node set, with a zero axis, an axis out of a 2D model's plane, a negative stiffness.
choc_cli_input_error(pressure_side_set check bad_pressure_side_set.xml
  "parameter 'Analyses/lagrange/Pressures/normal load/Side Set' = 'PAD_UPPER': no side set 'PAD_UPPER' in the mesh .side sets: PAD_BOTTOM, PAD_TOP")
choc_cli_input_error(pressure_ramp check bad_pressure_ramp.xml
  "parameter 'Analyses/lagrange/Pressures/normal load/Ramp Time' = '-0.07': out of range. valid: a number in .0, inf.")
choc_cli_input_error(spring_node_set check bad_spring_node_set.xml
  "parameter 'Model/Springs/ties/Node Set' = 'PAD_SPRINGS': no node set of that name in the mesh. did you mean 'PAD_SPRING'")
choc_cli_input_error(spring_zero_direction check bad_spring_zero_direction.xml
  "parameter 'Model/Springs/ties/Direction' = '0 0 0': a spring's axis needs a non-zero direction. give 'x y z' with a non-zero component")
choc_cli_input_error(spring_direction_2d check bad_spring_direction_2d.xml
  "parameter 'Model/Springs/ties/Direction' = '1 0 1': a 2D model moves in the x-y plane. give a direction with z = 0")
choc_cli_input_error(spring_stiffness check bad_spring_stiffness.xml
  "parameter 'Model/Springs/ties/Stiffness' = '-12000': out of range. valid: a number in .0, inf.")
# Finite strain (Model/Blocks/<name>/Strain, Model/Materials/<name>/Model): a linear elastic
# material on a finite-strain block, a hyperelastic one on a small-strain block, a beam in
# finite strain, a modal transient of a finite-strain model.
choc_cli_input_error(finite_linear_material check bad_finite_linear_material.xml
  "parameter 'Model/Blocks/PAD/Strain' = 'finite': material 'pad' is 'linear elastic', a small-strain law. set 'Model/Materials/pad/Model' = 'Saint Venant-Kirchhoff' .the same E and nu in finite strain. or 'neo-Hookean'")
choc_cli_input_error(small_hyperelastic check bad_small_hyperelastic.xml
  "parameter 'Model/Materials/pad/Model' = 'neo-Hookean': a finite-strain law on block 'PAD', whose 'Strain' is 'small'. set 'Model/Blocks/PAD/Strain' = 'finite', or the material's 'Model' = 'linear elastic'")
choc_cli_input_error(finite_beam check bad_finite_beam.xml
  "parameter 'Model/Blocks/POU1/Strain' = 'finite': beams .BEAM2. are small-strain in choc. set 'Strain' = 'small' on block 'POU1'")
choc_cli_input_error(finite_modal_transient check bad_finite_modal_transient.xml
  "parameter 'Model/Blocks/POU1/Strain' = 'finite': a modal transient .'reduced'. superposes the modes of the linear model. use a direct 'Transient' analysis for finite strain, or 'Strain' = 'small'")
choc_cli_input_error(momentum_axisymmetric check bad_momentum_axisymmetric.xml
  "parameter 'Analyses/axisymmetric/History' = 'SPHERE:PY': a node set's momentum is not recorded in axisymmetry. use a 3D or plane-strain model")
choc_cli_input_error(follower_small_strain check bad_follower_small_strain.xml
  "parameter 'Analyses/bend/Pressures/end/Follower' = 'true': a follower pressure makes the model nonlinear and needs a block with Strain = finite. set Strain = finite on the loaded block, or Follower = false .a dead load on the reference faces.")
choc_cli_input_error(follower_cg check bad_follower_cg.xml
  "parameter 'Analyses/bend/Pressures/end/Follower' = 'true': the load stiffness of a follower pressure is not symmetric, which CG cannot solve. use 'Linear Solver/Method' = Direct, GMRES or auto with follower pressures")
choc_cli_input_error(follower_small_block check bad_follower_small_block.xml
  "parameter 'Analyses/push/Pressures/face/Side Set' = 'CNT_POU2': has faces of block 'POU2', whose Strain is small: a follower pressure loads finite-strain blocks. set Strain = finite on that block, or Follower = false")
choc_cli_input_error(plastic_no_yield check bad_plastic_no_yield.xml
  "parameter 'Model/Materials/steel/Yield Stress': is missing: 'J2 plasticity' needs the initial yield stress. give 'Yield Stress' > 0 .Pa.")
choc_cli_input_error(mooney_rivlin_no_bulk check bad_mooney_rivlin_no_bulk.xml
  "parameter 'Model/Materials/rubber/Bulk Modulus': is missing: 'Mooney-Rivlin' needs it. give 'Bulk Modulus' > 0 .Pa.")
choc_cli_input_error(mooney_rivlin_young check bad_mooney_rivlin_young.xml
  "parameter 'Model/Materials/rubber/Young's Modulus' = '3e.06': is not a parameter of 'Mooney-Rivlin'. give its own constants: 'Mooney-Rivlin C10', 'Mooney-Rivlin C01' and 'Bulk Modulus'")
choc_cli_input_error(plastic_hardening check bad_plastic_hardening.xml
  "parameter 'Model/Materials/steel/Hardening Modulus' = '-1e.09': out of range. valid: a number in .0, inf.")
choc_cli_input_error(flow_curve_softening check bad_flow_curve_softening.xml
  "parameter 'Model/Materials/steel': J2 plasticity material, 'Flow Curve': the flow stress must not decrease .softening is not supported., but 2.8e.08 Pa follows 3e.08 Pa")
choc_cli_input_error(flow_curve_pairs check bad_flow_curve_pairs.xml
  "parameter 'Model/Materials/steel/Flow Curve' = '0 250e6 0.05': the curve has 3 numbers. give pairs 'plastic_strain stress .Pa.', the first at plastic strain 0")
choc_cli_input_error(johnson_cook_exponent check bad_johnson_cook_exponent.xml
  "parameter 'Model/Materials/steel': Johnson-Cook material: needs 'Johnson-Cook n' in .0, 1., got 1.5")
choc_cli_input_error(johnson_cook_no_melting check bad_johnson_cook_no_melting.xml
  "parameter 'Model/Materials/steel': Johnson-Cook material: needs 'Melting Temperature' above 'Reference Temperature' .20., got 0")
choc_cli_input_error(johnson_cook_melted check bad_johnson_cook_melted.xml
  "parameter 'Model/Materials/steel': Johnson-Cook material: 'Initial Temperature' 1600 is at or above the melting temperature 1540")
choc_cli_input_error(damage_fit check bad_damage_fit.xml
  "parameter 'Model/Materials/steel/Johnson-Cook D1' = '-0.09': out of range. valid: a number in .0, inf.")
choc_cli_input_error(damage_without_johnson_cook check bad_damage_without_johnson_cook.xml
  "parameter 'Model/Materials/steel/Damage' = 'Johnson-Cook': Johnson-Cook damage needs the Johnson-Cook flow stress .its reference rate and temperatures.. the material's 'Model' is 'J2 plasticity'. set 'Model' = 'Johnson-Cook', or 'Damage' = 'none'")
choc_cli_input_error(plastic_modal_transient check bad_plastic_modal.xml
  "parameter 'Model/Blocks/BEAM': a modal transient .'bend'. superposes the modes of the linear model. block 'BEAM' is plastic. use a direct 'Transient' analysis for plasticity, or a 'linear elastic' material")
choc_cli_input_error(plastic_beam check bad_plastic_beam.xml
  "parameter 'Model/Materials/steel/Model' = 'J2 plasticity': beams .BEAM2. are linear elastic in choc .block 'POU1'.. give the beams a 'linear elastic' material")
choc_cli_input_error(fbar_small_strain check bad_fbar_small_strain.xml
  "parameter 'Model/Blocks/BAR/Formulation' = 'F-bar': F-bar is for blocks in finite strain of elements with several points .HEX8, HEX20, TET10, QUAD4, QUAD8, TRI6.. block 'BAR' has QUAD4 elements and 'Strain' = 'small'. set 'Strain' = 'finite', or 'Formulation' = 'standard'")
choc_cli_input_error(momentum_modal check bad_momentum_modal.xml
  "parameter 'Analyses/reduced/History' = 'N1:PZ': a node set's momentum is recorded by the direct transient only. record it in a 'Transient' analysis, or record velocities here")
# Newton's line search and the contact status timing: only their listed choices.
choc_cli_input_error(line_search check bad_line_search.xml
  "parameter 'Analyses/impact/Newton/Line Search' = 'yes': is not a valid choice. did you mean 'on'.? valid: one of 'auto', 'on', 'off'")
choc_cli_input_error(status_update check bad_status_update.xml
  "parameter 'Analyses/impact/Contact/Status Update' = 'sometimes': is not a valid choice. valid: one of 'auto', 'each correction', 'converged solve'")
# F-bar on a one-point element: nothing to average (TET4 locks in plastic flow: TET10 F-bar).
choc_cli_input_error(fbar_tet4 check bad_fbar_tet4.xml
  "parameter 'Model/Blocks/LOWER/Formulation' = 'F-bar': F-bar is for blocks in finite strain of elements with several points .HEX8, HEX20, TET10, QUAD4, QUAD8, TRI6.. block 'LOWER' has TET4 elements and 'Strain' = 'finite'. mesh the block with TET10 elements .gmsh -order 2., or set 'Formulation' = 'standard'")
# One-point integration with hourglass control: HEX8 (3D) and QUAD4 (plane strain) blocks computed
# element by element (finite strain or plastic), with a positive hourglass coefficient.
choc_cli_input_error(one_point_tet4 check bad_one_point_tet4.xml
  "parameter 'Model/Blocks/LOWER/Formulation' = 'one-point': one-point integration with hourglass control is for HEX8 in 3D and QUAD4 in plane strain. block 'LOWER' has TET4 elements. mesh the block with HEX8 elements, or TET10 elements with 'Formulation' = 'F-bar'")
choc_cli_input_error(one_point_small_strain check bad_one_point_small.xml
  "parameter 'Model/Blocks/UPPER/Formulation' = 'one-point': block 'UPPER' is small-strain linear elastic .an assembled stiffness, fully integrated.. set 'Strain' = 'finite' .and a hyperelastic material., or 'Formulation' = 'standard'")
choc_cli_input_error(hourglass_coefficient check bad_hourglass_coefficient.xml
  "parameter 'Model/Blocks/UPPER/Hourglass Coefficient' = '0': out of range. valid: a number in .0, 1.")
# Kinematic hardening: small strain only, and not negative.
choc_cli_input_error(kinematic_finite check bad_kinematic_finite.xml
  "parameter 'Model/Materials/steel/Kinematic Hardening Modulus' = '1e.10': kinematic hardening is small-strain only. block 'BEAM' has 'Strain' = 'finite'. set the block's 'Strain' = 'small', or 'Kinematic Hardening Modulus' = 0")
choc_cli_input_error(kinematic_negative check bad_kinematic_negative.xml
  "parameter 'Model/Materials/steel/Kinematic Hardening Modulus' = '-1e.09': out of range. valid: a number in .0, inf.")
# The contact velocity update and the normal contact mass are implicit schemes' treatments.
choc_cli_input_error(velocity_update_explicit check bad_velocity_update_explicit.xml
  "parameter 'Analyses/impact/Contact Mass' = 'velocity update': is an implicit scheme's treatment .central differences enforce contact on the lumped mass.. use 'standard' or 'auto' with central differences")
choc_cli_input_error(normal_mass_explicit check bad_normal_mass_explicit.xml
  "parameter 'Analyses/impact/Contact Mass' = 'normal': is an implicit scheme's treatment .central differences enforce contact on the lumped mass.. use 'standard' or 'auto' with central differences")
