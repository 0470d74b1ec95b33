"""The CLI scripts' common start: their arguments (CHOC SOURCE_DIR WORK_DIR) and the scale
scene's bars at 9,648 unknowns (3 x 3 x 100 HEX8 per bar, tools/build/make-scale-mesh.sh) in WORK_DIR."""
import os
import subprocess
import sys


def bars_3_100():
    """Returns (choc, source dir, work dir, mesh path), the mesh made in the work directory."""
    choc, src, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    mesh = os.path.join(work, "bars_3_100.exo")
    subprocess.run([os.path.join(src, "tools", "build", "make-scale-mesh.sh"), choc, "3", "100", mesh], check=True,
                   stdout=subprocess.DEVNULL)
    return choc, src, work, mesh
