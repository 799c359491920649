"""A scene with errors raises SceneError with the report `hscene check`
prints; warnings go through Python's warnings."""

import subprocess
import warnings

import pytest

import hscene

BROKEN = """Globals { resolution = (32, 32); }
Objects {
    Sphere (0, 0, 0.3), 0.1, #nowhere;
}
"""


def test_errors_raise_scene_error_with_the_located_report(hscene_bin, tmp_path):
    with pytest.raises(hscene.SceneError) as caught:
        hscene.Scene.from_str(BROKEN, name="broken.hsc")
    message = str(caught.value)
    path = tmp_path / "broken.hsc"
    path.write_text(BROKEN)
    r = subprocess.run(
        [hscene_bin, "check", "--color", "never", str(path)],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert r.returncode != 0
    # The same report, but for the file name each was given.
    assert message == r.stdout.replace(str(path), "broken.hsc").rstrip()
    assert "[broken.hsc:3:30]" in message
    (first, *_) = caught.value.diagnostics
    assert first.severity == "error"
    assert first.line == 3 and first.column > 1
    assert first.code.startswith("HSC")
    assert "nowhere" in first.message


def test_warnings_go_through_warnings_warn():
    text = """Globals { resolution = (16, 16); }
Points { (0.1, 0.1, 0.1); }
Lights { (0.1, 0.2, -0.1), (1, 1, 1), (0.5, 0.5, 0.5); }
BRDFs { red: diffuse = (0.9, 0.2, 0.15); }
Objects { Sphere (0, 0, 0.4), 0.1, #red; }
"""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scene = hscene.Scene.from_str(text, name="w.hsc")
    assert any(issubclass(w.category, hscene.SceneWarning) for w in caught), caught
    assert scene.diagnostics and scene.diagnostics[0].severity == "warning"


def test_unreadable_files(tmp_path):
    with pytest.raises(OSError):
        hscene.Scene.from_file(tmp_path / "missing.hsc")
    with pytest.raises(OSError):
        hscene.Scene.from_file(tmp_path)
