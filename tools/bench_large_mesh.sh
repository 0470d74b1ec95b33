#!/usr/bin/env bash
# Reads, partitions and assembles a large TET10 mesh made by gmsh on 2 MPI ranks, printing the
# time and every rank's peak memory of each phase (issue 13). Not a test: `make bench-mesh`.
# usage: tools/bench_large_mesh.sh [BUILD_DIR] [N]   (N elements across the block: 20 gives
#        meshes/cantilever_block.geo in TET10 with about 1.05 million unknowns)
set -euo pipefail
top="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$top/build}"
n="${2:-20}"
work="$top/results/bench_large_mesh"
mkdir -p "$work"
mesh="$work/block_tet10_n$n.msh"
if [ ! -f "$mesh" ]; then
  SECONDS=0
  gmsh -3 -order 2 -setnumber n "$n" -setnumber hex 0 -format msh41 \
    "$top/meshes/cantilever_block.geo" -o "$mesh" > "$work/gmsh.log" 2>&1
  echo "gmsh: ${SECONDS} s for $mesh ($(du -h "$mesh" | cut -f1))"
fi
cat > "$work/deck.xml" <<XML
<ParameterList name="large-tet10">
  <Parameter name="Title" type="string" value="TET10 block, $n elements across: read, partition, assembly"/>
  <ParameterList name="Mesh"><Parameter name="File" type="string" value="$mesh"/></ParameterList>
  <ParameterList name="Model">
    <ParameterList name="Materials"><ParameterList name="steel">
      <Parameter name="Young's Modulus" type="double" value="2e11"/>
      <Parameter name="Poisson's Ratio" type="double" value="0.3"/>
      <Parameter name="Density" type="double" value="7800"/>
    </ParameterList></ParameterList>
    <ParameterList name="Blocks"><ParameterList name="block">
      <Parameter name="Material" type="string" value="steel"/>
    </ParameterList></ParameterList>
    <ParameterList name="Dirichlet"><ParameterList name="clamp">
      <Parameter name="Node Set" type="string" value="clamped"/>
      <Parameter name="Components" type="string" value="all"/>
    </ParameterList></ParameterList>
  </ParameterList>
  <ParameterList name="Analyses"><ParameterList name="transient">
    <Parameter name="Type" type="string" value="Transient"/>
    <Parameter name="Time Step" type="double" value="1e-6"/>
    <Parameter name="End Time" type="double" value="1e-6"/>
    <ParameterList name="Linear Solver"><Parameter name="Method" type="string" value="CG"/></ParameterList>
  </ParameterList></ParameterList>
</ParameterList>
XML
# 'choc check' sets the transient up: mesh read, partition, stiffness and mass assembly.
mpirun --allow-run-as-root --oversubscribe --bind-to none -np 2 "$build/choc" check "$work/deck.xml" \
  | grep -E "^  (mesh read|element geometry|partition|stiffness|mass)|^partition:|is valid"
