#!/usr/bin/env python3
"""Runs raygate's GitLab CI template (ci/gitlab/raygate.gitlab-ci.yml) under gitlab-ci-local, a
local GitLab runner (shell executor, one isolated copy of the project per job, no Docker), on a
fixture tracer repository with a real `origin`, the real raygate, and a local stand-in for the
GitLab API (fake_forge.py):

1. a push pipeline on main: raygate:record runs and records the tracer, pushes the document and
   the dashboard to origin's raygate-results branch, and keeps raygate-out/ (results.json,
   report.html, verdict.json, the JUnit file, dashboard/history.html) as artifacts; `pages`
   (extending .raygate:pages) publishes the dashboard as public/index.html;
2. a merge request pipeline from branch slower (four times slower): raygate:compare imports the
   history from the results branch, finds the regression, fails with exit 1, writes a JUnit file
   with the failure, and posts ONE MR note with the hidden marker;
3. the same merge request again: the note is edited in place.

The template is included unchanged (`include: local:` of a copy); raygate is not built by it
(RAYGATE_SRC_DIR / RAYGATE_BIN_DIR name this source tree and this build).

usage: gitlab_template_test.py RAYGATE_BIN_DIR RAYGATE_SOURCE_DIR
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree

import fake_forge
import tracer_repo

PINNED = "4.64.1"   # ci/install-deps test installs this version
MARKER = "<!-- raygate-report -->"

PROJECT_CI = """include:
  - local: ci/raygate.gitlab-ci.yml
variables:
  RAYGATE_ADAPTER: make-nff
  RAYGATE_SUITE: raygate/suite.json
  RAYGATE_SRC_DIR: "{source}"
  RAYGATE_BIN_DIR: "{bin}"
pages:
  extends: .raygate:pages
"""


def check(condition, what, log=""):
    if not condition:
        print(log)
        raise AssertionError(what)
    print(f"ok   {what}")


def gitlab_ci_local(project, variables, *jobs):
    args = ["gitlab-ci-local", "--force-shell-executor", "--shell-isolation",
            "--json-schema-validation=false", "--no-color", *jobs]
    for name, value in variables.items():
        args += ["--variable", f"{name}={value}"]
    env = dict(os.environ, GCL_IGNORE_PREDEFINED_VARS="CI_PIPELINE_SOURCE,CI_API_V4_URL,CI_PROJECT_ID,"
               "CI_MERGE_REQUEST_IID,CI_MERGE_REQUEST_TARGET_BRANCH_NAME,CI_MERGE_REQUEST_SOURCE_BRANCH_NAME")
    r = subprocess.run(args, cwd=project, env=env, capture_output=True, text=True, timeout=600)
    return r.returncode, r.stdout + r.stderr


def artifact(project, job, path):
    """A job's artifact file, where gitlab-ci-local keeps it (the job name made file-safe)."""
    for folder in (project / ".gitlab-ci-local" / "artifacts").iterdir():
        candidate = folder / path
        if folder.name.endswith(job.split(":")[-1]) and candidate.exists():
            return candidate
    return None


def junit_cases(path):
    """(names of the test cases, names of those failed) of a JUnit file."""
    cases = list(ElementTree.parse(path).getroot().iter("testcase"))
    names = [f"{c.get('classname')} {c.get('name')}" for c in cases]
    return names, [n for n, c in zip(names, cases) if c.find("failure") is not None]


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    if shutil.which("gitlab-ci-local") is None:
        print("FAIL gitlab-ci-local is not installed: `ci/install-deps test` installs it "
              f"(npm install -g gitlab-ci-local@{PINNED})")
        return 1
    bin_dir, source = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
    with tempfile.TemporaryDirectory(prefix="raygate-gl-") as tmp, fake_forge.Forge("test-token") as forge:
        tmp = pathlib.Path(tmp)
        project = tracer_repo.make(tmp, source)
        origin = tmp / "origin.git"
        (project / "ci").mkdir()
        shutil.copy(source / "ci" / "gitlab" / "raygate.gitlab-ci.yml", project / "ci")
        (project / ".gitlab-ci.yml").write_text(PROJECT_CI.format(source=source, bin=bin_dir))
        # gitlab-ci-local reads a local include from the commit: both branches carry the CI files.
        tracer_repo.git(project, "add", "-A")
        tracer_repo.git(project, "commit", "--quiet", "-m", "CI: raygate")
        tracer_repo.git(project, "checkout", "--quiet", "slower")
        tracer_repo.git(project, "cherry-pick", "main")
        tracer_repo.git(project, "checkout", "--quiet", "main")
        tracer_repo.git(project, "push", "--quiet", "origin", "main", "slower")
        tracer_repo.git(project, "remote", "set-head", "origin", "main")

        # 1. Push pipeline on main.
        code, log = gitlab_ci_local(project, {"RAYGATE_EXTRA_ARGS": "--max-rounds 2"})
        check(code == 0 and "PASS  raygate:record" in log and "PASS  pages" in log,
              "push pipeline: raygate:record and pages passed", log)
        for name in ("results.json", "report.html", "verdict.json", "junit.xml", "dashboard/history.html"):
            check(artifact(project, "raygate:record", f"raygate-out/{name}") is not None,
                  f"push pipeline: artifact raygate-out/{name}", log)
        cases, failures = junit_cases(artifact(project, "raygate:record", "raygate-out/junit.xml"))
        check(any("tetra" in c for c in cases) and not failures,
              f"push pipeline: the JUnit file has the scene, not failed ({cases}, {failures})")
        page = artifact(project, "pages", "public/index.html")
        check(page is not None and "<svg" in page.read_text(), "pages: the dashboard is public/index.html", log)
        files = tracer_repo.git(origin, "ls-tree", "-r", "--name-only", "raygate-results").split()
        check("index.html" in files and sum(f.startswith("results/") for f in files) == 1,
              f"push pipeline: origin's raygate-results branch has the document and the dashboard ({files})", log)

        # 2. Merge request pipeline from branch slower.
        tracer_repo.git(project, "checkout", "--quiet", "slower")
        mr = {"CI_PIPELINE_SOURCE": "merge_request_event", "CI_MERGE_REQUEST_TARGET_BRANCH_NAME": "main",
              "CI_MERGE_REQUEST_SOURCE_BRANCH_NAME": "slower", "CI_MERGE_REQUEST_IID": "5",
              "CI_API_V4_URL": f"{forge.url}/api/v4", "CI_PROJECT_ID": "42", "RAYGATE_NOTE_TOKEN": "test-token"}
        # 12 rounds: the fewest from which compare decides one scene (docs/statistics.md §6a).
        code, log = gitlab_ci_local(project, dict(mr, RAYGATE_EXTRA_ARGS="--max-rounds 12"))
        check(code != 0 and "FAIL  raygate:compare" in log and "raygate: REGRESSION (exit 1)" in log
              and not re.search(r"(PASS|FAIL)\s+raygate:record", log),
              "merge request pipeline: only raygate:compare ran, and it failed on the regression", log)
        check("results-branch: 1 documents from origin raygate-results" in log,
              "merge request pipeline: the history was imported from the results branch", log)
        _, failures = junit_cases(artifact(project, "raygate:compare", "raygate-out/junit.xml"))
        check(any("tetra" in f for f in failures),
              f"merge request pipeline: the JUnit file names the regressed scene ({failures})", log)
        notes = forge.comments.get("5", [])
        check(len(notes) == 1 and notes[0]["body"].startswith(MARKER) and "REGRESSED" in notes[0]["body"],
              "merge request pipeline: one MR note with the marker and the verdict", log)
        first_id = notes[0]["id"]

        # 3. The same merge request again (one round: no verdict): the note is edited.
        code, log = gitlab_ci_local(project, dict(mr, RAYGATE_EXTRA_ARGS="--max-rounds 1"))
        notes = forge.comments.get("5", [])
        check(len(notes) == 1 and notes[0]["id"] == first_id and "REGRESSED" not in notes[0]["body"]
              and ("PUT", f"/api/v4/projects/42/merge_requests/5/notes/{first_id}") in forge.requests,
              "merge request, second push: the same note was updated in place", log)
    return 0


if __name__ == "__main__":
    sys.exit(main())
