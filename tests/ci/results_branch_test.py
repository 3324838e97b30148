#!/usr/bin/env python3
"""ci/results-branch against real git repositories: two CI jobs record at the same time.

Job B prepares its commit on the results branch, and just before B's push lands, job A pushes
its own (a pre-push hook in B's clone plays job A, once). B's push is refused as not a fast-
forward; results-branch must fetch, rebuild its commit on top of A's and push again, so the
branch ends with both documents and the job's checkout (HEAD, index, files) is untouched. Then
`pull` imports both documents into a new store.

usage: results_branch_test.py RAYGATE_EXECUTABLE RAYGATE_SOURCE_DIR
"""
import os
import pathlib
import subprocess
import sys
import tempfile

import tracer_repo


def run(cwd, *args, env=None):
    return subprocess.run(args, cwd=cwd, env=env, check=True, capture_output=True, text=True).stdout


def main():
    raygate, source = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
    script = source / "ci" / "results-branch"
    with tempfile.TemporaryDirectory(prefix="raygate-rb-") as tmp:
        tmp = pathlib.Path(tmp)
        job_a = tracer_repo.make(tmp, source)
        origin = tmp / "origin.git"
        job_b = tmp / "job-b"
        tracer_repo.git(tmp, "clone", "--quiet", str(origin), str(job_b))
        env = dict(os.environ, RAYGATE=str(raygate))
        # results-branch stores bytes; pull parses them. Two documents of the same commit, pushed
        # within the same second: both must be kept.
        doc_a, doc_b = tmp / "a.json", tmp / "b.json"
        doc_a.write_text('{"schema_version": 1, "job": "a"}\n')
        doc_b.write_text('{"schema_version": 1, "job": "b"}\n')

        # Job A's push, run from B's pre-push hook the first time B pushes.
        hook = job_b / ".git" / "hooks" / "pre-push"
        hook.write_text(f"#!/bin/sh\n[ -e {tmp}/raced ] && exit 0\ntouch {tmp}/raced\n"
                        f"cd {job_a} && {script} push {doc_a} >/dev/null\n")
        hook.chmod(0o755)
        head_before = tracer_repo.git(job_b, "rev-parse", "HEAD")
        out = run(job_b, str(script), "push", str(doc_b), env=env)
        assert (tmp / "raced").exists(), "the hook did not run: the race was not staged"
        assert "push attempt 1 refused" in out, out
        files = tracer_repo.git(origin, "ls-tree", "-r", "--name-only", "raygate-results").split()
        assert len([f for f in files if f.startswith("results/")]) == 2, files
        log = tracer_repo.git(origin, "log", "--format=%s", "raygate-results").splitlines()
        assert len(log) == 2 and all("[skip ci]" in s for s in log), log
        assert tracer_repo.git(job_b, "rev-parse", "HEAD") == head_before, "HEAD moved"
        assert tracer_repo.git(job_b, "status", "--porcelain") == "", "the checkout changed"
        print("ok   a push that lost the race was retried on top of the other job's: both documents kept")

        # pull: the branch's documents go through raygate import, which refuses these stand-ins
        # as results documents; none imported is exit 3, each named.
        r = subprocess.run([str(script), "pull", str(tmp / "store.db")], cwd=job_b, env=env,
                           capture_output=True, text=True)
        assert r.returncode == 3, r.stdout + r.stderr
        assert r.stderr.count("warning: skipped results/") == 2, r.stderr
        assert "not a raygate results document" in r.stderr, r.stderr
        print("ok   pull hands every document of the branch to raygate import")

        # A sweep: one unreadable file in the branch made import (all or nothing) take none, and
        # the history started empty on every later push. The readable ones are imported.
        real = source / "tests" / "harness" / "store" / "fixtures" / "main-60ebc9f-run.json"
        garbage = tmp / "garbage.json"
        garbage.write_text("garbage{")
        run(job_b, str(script), "push", str(real), env=env)
        run(job_b, str(script), "push", str(garbage), env=env)
        r = subprocess.run([str(script), "pull", str(tmp / "store.db")], cwd=job_b, env=env,
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stdout + r.stderr
        assert "1 of 4 documents" in r.stdout, r.stdout
        assert r.stderr.count("warning: skipped results/") == 3 and "not JSON" in r.stderr, r.stderr
        stored = subprocess.run([str(raygate), "export", "--store", str(tmp / "store.db"), "-o",
                                 str(tmp / "exported")], capture_output=True, text=True)
        assert stored.returncode == 0 and len(list((tmp / "exported").iterdir())) == 1, stored.stderr
        print("ok   an unreadable document in the branch is skipped and named; the others are imported")
    return 0


if __name__ == "__main__":
    sys.exit(main())
