#!/usr/bin/env bash
# Regenerates the committed benchmark meshes with choc's own generator.
# Usage: meshes/make-meshes.sh [path/to/choc]   (default build/choc)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
choc="${1:-$here/../build/choc}"
# SDNL111 A: 2 x 50 two-node beams along x, gap J0 = 1e-5 between A and C.
"$choc" mesh --dim 1 --axis x --along1 50 --along2 50 --gap 1e-5 -o "$here/sdnl111_1d.exo"
# SDNL111 B: the same, with node A moved 1.1e-5 towards C (A lies 1e-6 beyond C).
"$choc" mesh --dim 1 --axis x --along1 50 --along2 50 --gap 1e-5 --shift-a -1.1e-5 \
  -o "$here/sdnl111b_1d.exo"
# SDNL111 C, D, E: 2 x 50 HEX8 along z, 1 x 1 across, section 0.02 x 0.02.
"$choc" mesh --dim 3 --axis z --along1 50 --along2 50 --across1 1 --across2 1 \
  --width 0.02 --height 0.02 --gap 1e-5 -o "$here/sdnl111_3d.exo"
# Beyond the reference (input/sdnl111a_rigid.xml): the 1D scene with 600 beams per bar.
"$choc" mesh --dim 1 --axis x --along1 600 --along2 600 --gap 1e-5 -o "$here/sdnl111_1d_600.exo"
# Beyond the reference (input/sdnl111c_accurate.xml): the 3D bars with 400 HEX8 along each.
"$choc" mesh --dim 3 --axis z --along1 400 --along2 400 --across1 1 --across2 1 \
  --width 0.02 --height 0.02 --gap 1e-5 -o "$here/sdnl111_3d_400.exo"
# Saint-Venant's problem (input/saint_venant.xml): a 0.05 m striker (5 HEX8, declared rigid)
# touching a 1 m bar of 100 HEX8 along z, section 0.02 x 0.02.
"$choc" mesh --dim 3 --axis z --along1 5 --along2 100 --length1 0.05 --length2 1 --across1 1 --across2 1 \
  --width 0.02 --height 0.02 --gap 0 -o "$here/saint_venant.exo"
# The gmsh example: the same bars in TET10 (needs the gmsh command, Debian package gmsh).
gmsh -3 -order 2 -format msh41 "$here/sdnl111_3d_bars.geo" -o "$here/sdnl111_3d_tet10.msh" > /dev/null
# The 2D section (plane strain, axisymmetric): the bars in QUAD8.
gmsh -2 -order 2 -format msh41 "$here/sdnl111_2d.geo" -o "$here/sdnl111_2d_quad8.msh" > /dev/null
# SDNV100: the bar dropped on a rigid wall, 20 HEX8 along.
gmsh -3 -format msh41 "$here/sdnv100_bar.geo" -o "$here/sdnv100_bar.msh" > /dev/null
gmsh -3 -format msh41 -setnumber n 1000 "$here/sdnv100_bar.geo" -o "$here/sdnv100_bar_1000.msh" > /dev/null
# Hertz: the sphere (axisymmetric half disc) and its lower half for the static press.
gmsh -2 -order 2 -format msh41 "$here/hertz_axisymmetric.geo" -o "$here/hertz_axisymmetric.msh" > /dev/null
gmsh -2 -order 2 -format msh41 "$here/hertz_hemisphere.geo" -o "$here/hertz_hemisphere.msh" > /dev/null
# Two such spheres colliding head on (meshed bodies in contact, node to face).
gmsh -2 -order 2 -format msh41 "$here/hertz_two_spheres.geo" -o "$here/hertz_two_spheres.msh" > /dev/null
# A sphere hitting a rigid plane obliquely (TET10, the half z >= 0), for frictional contact.
gmsh -3 -order 2 -format msh41 "$here/oblique_sphere.geo" -o "$here/oblique_sphere.msh" > /dev/null
# A steel L-bracket (TET10) for the drop tests.
gmsh -3 -order 2 -format msh41 "$here/bracket.geo" -o "$here/bracket.msh" > /dev/null
# A thick-walled neo-Hookean sphere inflated (finite strain): axisymmetric QUAD8 and a 3D TET10 octant.
gmsh -2 -order 2 -format msh41 "$here/thick_sphere_axisymmetric.geo" -o "$here/thick_sphere_axisymmetric.msh" > /dev/null
gmsh -3 -order 2 -format msh41 "$here/thick_sphere_octant.geo" -o "$here/thick_sphere_octant.msh" > /dev/null
# A rubber ball (finite strain): the Hertz half disc in TRI6 of 0.5 mm throughout.
gmsh -2 -order 2 -format msh41 -setnumber h 5e-4 -setnumber H 5e-4 "$here/hertz_axisymmetric.geo" \
  -o "$here/rubber_ball.msh" > /dev/null
# A slender cantilever (finite strain, the elastica): 16 x 2 x 1 HEX20 along a beam of L / h = 50.
gmsh -3 -order 2 -format msh41 -setnumber nx 16 -setnumber hex 1 "$here/elastica_beam.geo" \
  -o "$here/elastica_beam_hex20.msh" > /dev/null
# The same with 32 HEX20 along (input/elastica_moment.xml: the beam rolled into a ring).
gmsh -3 -order 2 -format msh41 -setnumber nx 32 -setnumber hex 1 "$here/elastica_beam.geo" \
  -o "$here/elastica_beam_hex20_32.msh" > /dev/null
# The Taylor bar (plasticity): the axisymmetric rectangle, 8 x 81 QUAD4 of 0.4 mm.
gmsh -2 -format msh41 "$here/taylor_bar_axisymmetric.geo" -o "$here/taylor_bar_axisymmetric.msh" > /dev/null
gmsh -3 -format msh41 -setnumber n 4 "$here/taylor_bar_3d.geo" -o "$here/taylor_bar_3d.msh" > /dev/null
# SDND101: the oscillator on a stop, one beam standing for the discrete spring and mass.
gmsh -1 -format msh41 "$here/sdnd101.geo" -o "$here/sdnd101.msh" > /dev/null
# SDNL32: the articulated beam, the deck's 11 nodes.
gmsh -1 -format msh41 "$here/sdnl32.geo" -o "$here/sdnl32.msh" > /dev/null
# SDND100: the oscillator with friction, one beam across the motion for the spring and mass.
gmsh -1 -format msh41 "$here/sdnd100.geo" -o "$here/sdnd100.msh" > /dev/null
# Sliding: a block pushed along a longer foundation, non-matching HEX8 faces.
gmsh -3 -format msh41 "$here/sliding_blocks.geo" -o "$here/sliding_blocks.msh" > /dev/null
# SDNL111 on non-matching meshes: bar 1 HEX8 3 x 3, bar 2 TET4.
gmsh -3 -format msh41 "$here/sdnl111_nonmatching.geo" -o "$here/sdnl111_nonmatching.msh" > /dev/null
# Contact patch test: HEX8 3 x 3 on TET4 4 x 4 triangles (tet = 0: matching HEX8).
gmsh -3 -format msh41 "$here/patch_test.geo" -o "$here/patch_test.msh" > /dev/null
# SDNV104: the pad on the frame in plane strain, QUAD4 and QUAD8.
gmsh -2 -format msh41 "$here/sdnv104.geo" -o "$here/sdnv104_quad4.msh" > /dev/null
gmsh -2 -order 2 -format msh41 "$here/sdnv104.geo" -o "$here/sdnv104_quad8.msh" > /dev/null
# Hertz in 3D: the quarter sphere in TET10, 0.1 mm near the first point of contact.
gmsh -3 -order 2 -format msh41 "$here/hertz_quarter.geo" -o "$here/hertz_quarter.msh" > /dev/null
# The copper bar probe (penalty contact with the non-dissipative schemes): the cylinder R = 3.2 mm,
# L = 32.4 mm in HEX8, an O-grid disk (16 segments on the circle) extruded in 24 layers.
gmsh -3 -format msh41 "$here/copper_bar.geo" -o "$here/copper_bar.msh" > /dev/null
# The compact block of the direct solvers' benchmark: a 0.1 m steel cube in 10 x 10 x 10 HEX8
# (tools/bench/bench_block_drop.py makes the larger ones with -setnumber n).
gmsh -3 -format msh41 "$here/compact_block.geo" -o "$here/compact_block.msh" > /dev/null
# Two stacked plates whose whole interface is in contact (input/stacked_plates.xml; 961 slave
# nodes at n = 30; tools/bench/bench_projected_gram.py makes the larger ones).
gmsh -3 -format msh41 -setnumber n 30 "$here/stacked_plates.geo" -o "$here/stacked_plates.msh" > /dev/null
# The block dropped on a meshed slab (input/block_on_slab.xml): the cube in 8 x 8 x 8 HEX8 on the
# slab in 16 x 16 x 3 (4,788 unknowns); tools/bench/bench_block_on_slab.py makes the 58,041-unknown
# one of issue 73 (n = 20, m = 40, k = 6).
gmsh -3 -format msh41 -setnumber n 8 -setnumber m 16 -setnumber k 3 "$here/block_on_slab.geo" -o "$here/block_on_slab.msh" > /dev/null
# A rigid box with three distinct principal moments (input/rigid_spin.xml).
gmsh -3 -format msh41 "$here/rigid_box.geo" -o "$here/rigid_box.msh" > /dev/null
