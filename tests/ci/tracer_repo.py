"""The fixture tracer (tests/fixtures/nff_tracer) as a tracer project's repository for the CI
template tests: branch main (the tracer), branch slower (every pixel traced four times: the same
image, about four times the time), a one-scene suite in raygate/suite.json, and a bare `origin`
holding both branches, as a CI checkout has.
"""
import pathlib
import subprocess

SUITE = """{
  "name": "tiny",
  "description": "the CI template tests: one small scene",
  "scenes": [
    {"id": "tetra", "scene": "tetra", "size": 4, "resolution": [128, 128]}
  ]
}
"""


def git(cwd, *args):
    return subprocess.run(["git", "-c", "user.name=raygate test", "-c", "user.email=test@raygate",
                           "-c", "init.defaultBranch=main", *args],
                          cwd=cwd, check=True, capture_output=True, text=True).stdout.strip()


def make(root, source_dir):
    """Creates root/origin.git and its clone root/tracer (on main); returns the clone's path."""
    root = pathlib.Path(root)
    fixture = pathlib.Path(source_dir) / "tests" / "fixtures" / "nff_tracer"
    origin = root / "origin.git"
    work = root / "tracer"
    git(root, "init", "--quiet", "--bare", str(origin))
    git(root, "init", "--quiet", str(work))
    fast = (fixture / "tracer.cpp").read_text()
    assert fast.count("constexpr int kPasses = 1;") == 1, "fixture tracer.cpp changed"
    (work / "tracer.cpp").write_text(fast)
    (work / "Makefile").write_text((fixture / "Makefile").read_text())
    (work / "raygate").mkdir()
    (work / "raygate" / "suite.json").write_text(SUITE)
    git(work, "add", "-A")
    git(work, "commit", "--quiet", "-m", "the tracer")
    git(work, "checkout", "--quiet", "-b", "slower")
    (work / "tracer.cpp").write_text(fast.replace("constexpr int kPasses = 1;", "constexpr int kPasses = 4;"))
    git(work, "commit", "--quiet", "-am", "trace every pixel four times")
    git(work, "checkout", "--quiet", "main")
    git(work, "remote", "add", "origin", str(origin))
    git(work, "push", "--quiet", "origin", "main", "slower")
    return work
