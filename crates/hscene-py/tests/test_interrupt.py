"""Ctrl-C stops a render within a second or two, as KeyboardInterrupt."""

import signal
import subprocess
import sys
import time

# The child takes Ctrl-C as an interactive Python does. A process started
# by a non-interactive shell's background job (a CI runner's, `nohup ... &`)
# inherits SIGINT ignored, and Python then installs no handler of its own.
CHILD = r"""
import signal, sys, time
signal.signal(signal.SIGINT, signal.default_int_handler)
import hscene
scene = hscene.Scene.from_str('''
Globals { resolution = (2000, 2000); samples = 64; to = (0, 0, 0.3); fov = 90; recursion_depth = 8; }
BRDFs { glass: diffuse = (0.1, 0.2, 0.3), trans = 0.8, refraction = 1.4; }
Lights { (0.1, 0.2, -0.1), (1, 1, 1), (0.5, 0.5, 0.5); }
Objects { Sphere (0, 0, 0.4), 0.3, #glass; Sphere (0.2, 0, 0.5), 0.2, #glass; }
''')
print("rendering", flush=True)
try:
    scene.render()
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(7)
print("finished", flush=True)
"""


def test_sigint_stops_a_long_render():
    child = subprocess.Popen(
        [sys.executable, "-c", CHILD],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert child.stdout.readline().strip() == "rendering"
        time.sleep(0.5)  # well into the render
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        code = child.wait(timeout=10)
        took = time.monotonic() - sent
    finally:
        if child.poll() is None:
            child.kill()
    out = child.stdout.read()
    assert code == 7, (code, out, child.stderr.read())
    assert "interrupted" in out
    assert took < 2.0, f"took {took:.2f} s to stop"
