"""Running an input of input/ from a CLI test script: the deck copied to the work directory with
its mesh paths made absolute, edited, and run; the script stops (naming the run) on a failure."""
import os
import subprocess
import sys


def run_deck(choc, src, work, deck_file, name, edit=lambda s: s, label="test"):
    """Runs input/<deck_file> edited by edit() as <work>/<name>.xml into <work>/<name>; returns
    (output directory, log)."""
    deck = open(os.path.join(src, "input", deck_file)).read()
    deck = edit(deck.replace('value="../meshes/', f'value="{src}/meshes/'))
    path = os.path.join(work, name + ".xml")
    with open(path, "w") as f:
        f.write(deck)
    out = os.path.join(work, name)
    r = subprocess.run([choc, "run", path, "-o", out], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{label}: {name}: choc exited {r.returncode}: {r.stderr.strip()}")
    return out, r.stdout
