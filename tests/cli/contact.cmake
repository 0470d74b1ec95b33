# Frame invariance of a contact scene (BENCHMARKS section 8, issue 14): SDNV100 (the bar on a
# rigid plane obstacle) with every component free, as drawn and turned by 0.7 rad about
# (1, 2, 0.5): the motion of N5 and N100 and the wall force seen in the turned frame equal the
# unturned ones to 1e-8 of their peaks (the scene is the same; only round-off differs), with
# the same Newton iterations and factorisations (10%), for penalty, continuous and Lagrange, and
# no energy balance above +0.1% of E0 at the default contact mass (BENCHMARKS section 8).
add_test(NAME cli.frame_invariance_sdnv100
         COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tools/frame_invariance.py
                 --build ${CMAKE_BINARY_DIR} --out ${CMAKE_CURRENT_BINARY_DIR}/work/frame_invariance)
set_tests_properties(cli.frame_invariance_sdnv100 PROPERTIES TIMEOUT 120 LABELS cli)

# Hertz's impact (BENCHMARKS section 2), axisymmetric: the sphere's peak force, contact duration
# and largest approach within a/R of Hertz (the order of the finite-sphere terms Hertz's
# half-space theory leaves out, which the static press measures: |F/F_Hertz - 1| <= a/R at
# every travel), the rebound velocity within 2% of 5 m/s and the energy balance never above
# +0.1% of E0 (tools/hertz.py).
add_test(NAME cli.hertz_axisymmetric
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/scripts/hertz.sh $<TARGET_FILE:choc>
                 ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/hertz)
set_tests_properties(cli.hertz_axisymmetric PROPERTIES TIMEOUT 300 LABELS cli)

# A rigid wall sliding tangentially under SDNV100's bar: CONTACT_SLIP = v t at every contact
# node (and 0 elsewhere), the normal contact and the deck's rows unchanged.
add_test(NAME cli.obstacle_slip
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/obstacle_slip.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/obstacle_slip)
set_tests_properties(cli.obstacle_slip PROPERTIES TIMEOUT 120 LABELS cli)

# Curved rigid obstacles: SDNV100's bar on a sphere and on a cylinder of radius 1e4 m equals the
# plane run within ten times the obstacles' departure from the plane over the face.
add_test(NAME cli.curved_obstacles
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/curved_obstacles.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/curved_obstacles)
set_tests_properties(cli.curved_obstacles PROPERTIES TIMEOUT 120 LABELS cli)

# SDNL32 modal or direct (issue 16): the modal transient on all 31 modes (no damping) equals the
# direct implicit transient with the stop as penalty contact of the tip node on a plane
# (input/sdnl32_direct.xml) to 1e-5 of the peak, and 10 modes do not (their truncation).
add_test(NAME cli.sdnl32_modal_equals_direct
         COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tools/modal_direct_study.py --check
                 --build ${CMAKE_BINARY_DIR} --out ${CMAKE_CURRENT_BINARY_DIR}/work/sdnl32_modal_direct)
set_tests_properties(cli.sdnl32_modal_equals_direct PROPERTIES TIMEOUT 300 LABELS cli)

# Shock links in the direct transient (issue 16): the same spring as a contact pair, a circle
# equal to the planes on a 1D motion, and a ring against the modal transient on all modes.
add_test(NAME cli.direct_links
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/direct_links.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/direct_links)
set_tests_properties(cli.direct_links PROPERTIES TIMEOUT 300 LABELS cli)

# Large sliding (issue 14): input/sliding.xml's block pushed across 22 faces of a stiff
# foundation keeps a closed contact with a pressure uniform to 1 %, slips as it moves, creates no
# energy; on an elastic foundation the dent follows the block only with 'Search' = current.
add_test(NAME cli.sliding
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/sliding.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/sliding)
set_tests_properties(cli.sliding PROPERTIES TIMEOUT 300 LABELS cli)

# Frame invariance of the search in the current configuration (BENCHMARKS section 8): the
# sliding scene turned as a rigid whole (mesh, velocity, loads) gives the same motion, contact
# force, nodal pressures and slips to 1e-8 of their peaks, the same cost within 10 %, and no
# energy growth.
add_test(NAME cli.frame_invariance_sliding
         COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tools/frame_invariance.py --scene sliding
                 --build ${CMAKE_BINARY_DIR} --out ${CMAKE_CURRENT_BINARY_DIR}/work/frame_invariance_sliding)
set_tests_properties(cli.frame_invariance_sliding PROPERTIES TIMEOUT 300 LABELS cli)

# The contact patch test (BENCHMARKS section 3): matching faces pass it to 1e-8; on
# non-matching faces (quadrilaterals on triangles) node to face's error is reported.
add_test(NAME cli.patch_test
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/scripts/patch_test.py
                 $<TARGET_FILE:choc> ${CMAKE_SOURCE_DIR} ${CMAKE_CURRENT_BINARY_DIR}/work/patch_test)
set_tests_properties(cli.patch_test PROPERTIES TIMEOUT 300 LABELS cli)

# Explicit central differences with Lagrange contact by forward increments (issue 17): SDNV100
# with every component free, as drawn and turned: the same motion to 1e-8 of the peak, no
# penetration of the wall (gaps >= -1e-12 of the motion), no energy growth above +0.1 % of E0.
add_test(NAME cli.frame_invariance_explicit_lagrange
         COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tools/frame_invariance.py --explicit --only lagrange
                 --build ${CMAKE_BINARY_DIR} --out ${CMAKE_CURRENT_BINARY_DIR}/work/frame_invariance_explicit_lagrange)
set_tests_properties(cli.frame_invariance_explicit_lagrange PROPERTIES TIMEOUT 120 LABELS cli)
