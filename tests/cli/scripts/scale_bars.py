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


def run_deck(choc, work, name, text, ranks=1, env=None):
    """Writes `text` to WORK/NAME.xml, runs it into WORK/NAME (under mpirun on `ranks` > 1; `env`:
    variables added to the environment) and returns its log; exits naming the run and the end of
    its output when choc fails."""
    path = os.path.join(work, name + ".xml")
    with open(path, "w") as f:
        f.write(text)
    cmd = [choc, "run", path, "-o", os.path.join(work, name)]
    if ranks > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--mca", "mpi_yield_when_idle", "1", "-np", str(ranks)] + cmd
    p = subprocess.run(cmd, capture_output=True, text=True, env=dict(os.environ, **(env or {})))
    if p.returncode != 0:
        sys.exit(f"{name}: choc exited {p.returncode}:\n{p.stdout[-2000:]}{p.stderr[-2000:]}")
    return p.stdout
