#!/usr/bin/env python3
"""Runs raygate's composite GitHub action (ci/github/action.yml) in a simulated runner
(github_runner.py) on a fixture tracer repository, with the real raygate, real git, a real
`origin`, and a local stand-in for the GitHub API (fake_forge.py):

0. the workspace belongs to `nobody` and the job runs as root, as in a `container:` job; before
   the action, raygate refuses it, names git's ownership check and the exact safe.directory fix,
   and opens it once the global git config says `safe.directory = *`;
1. a push to main: the action trusts the workspace (safe.directory), runs and records the
   tracer, pushes the document and the dashboard to the `raygate-results` branch of origin,
   writes the job summary and the artifact (results.json, report.html, junit.xml, ...), and
   saves the tracer's builds to the (emulated) Actions cache;
2. a pull_request event (branch slower, four times slower): the action imports the history from
   the results branch, compares, fails the gate with exit 1, writes GITHUB_OUTPUT's exit-code
   and the PR number for the fork path, and posts ONE comment with the hidden marker;
3. the same pull request again: the comment is edited in place, not added.

raygate's build step is not run (input raygate-bin: the binaries this build made).

usage: github_action_test.py RAYGATE_BIN_DIR RAYGATE_SOURCE_DIR
"""
import json
import os
import pathlib
import subprocess
import sys
import tempfile

import fake_forge
import github_runner
import tracer_repo

NOBODY = 65534
MARKER = "<!-- raygate-report -->"
SKIP = 77


def chown_tree(path, uid):
    for root, dirs, files in os.walk(path):
        for name in dirs + files:
            os.lchown(os.path.join(root, name), uid, uid)
    os.lchown(path, uid, uid)


def check(condition, what, runner=None):
    if not condition:
        if runner is not None:
            print("\n".join(runner.log))
        raise AssertionError(what)
    print(f"ok   {what}")


def job(root, workspace, forge, event_name, event, github, bin_dir, source, env, rounds):
    runner = github_runner.Runner(root, workspace, event_name, event,
                                  dict(github, api_url=forge.url, repository="octo/tracer",
                                       token="test-token", run_id="1"), env)
    steps = runner.run_action(source / "ci" / "github",
                              {"adapter": "make-nff", "suite": "raygate/suite.json",
                               "extra-args": f"--max-rounds {rounds} --max-seconds 20",
                               "raygate-bin": str(bin_dir)})
    print("     " + ", ".join(f"{name} {seconds:.1f} s" for name, seconds in runner.durations if seconds >= 1))
    return runner, steps


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    if os.getuid() != 0:
        print("SKIP: needs root, to give the workspace to another user as a container job has it")
        return SKIP
    bin_dir, source = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
    with tempfile.TemporaryDirectory(prefix="raygate-gh-") as tmp, fake_forge.Forge("test-token") as forge:
        tmp = pathlib.Path(tmp)
        workspace = tracer_repo.make(tmp, source)
        origin = tmp / "origin.git"
        chown_tree(workspace, NOBODY)
        home = tmp / "home"
        home.mkdir()
        env = {"HOME": str(home), "XDG_CONFIG_HOME": str(home / ".config"), "GIT_CONFIG_NOSYSTEM": "1"}

        # 0. The refusal, before anything trusts the workspace.
        r = subprocess.run([str(bin_dir / "raygate"), "run", "--repo", str(workspace), "--rev", "HEAD",
                            "--adapter", "make-nff", "--no-store"], env=dict(os.environ, **env),
                           capture_output=True, text=True, timeout=60)
        check(r.returncode == 2 and
              f"git config --global --add safe.directory {workspace}" in r.stderr + r.stdout,
              "a workspace owned by nobody is refused with the safe.directory fix, exit 2")
        # git's `safe.directory = *`, which libgit2 1.5 ignores, is honoured: the repository opens
        # (and the made-up revision is what fails).
        (home / ".gitconfig").write_text("[safe]\n\tdirectory = *\n")
        r = subprocess.run([str(bin_dir / "raygate"), "run", "--repo", str(workspace), "--rev", "no-such-rev",
                            "--adapter", "make-nff", "--no-store"], env=dict(os.environ, **env),
                           capture_output=True, text=True, timeout=60)
        check(r.returncode == 2 and "no-such-rev" in r.stderr + r.stdout and "git refuses" not in r.stderr + r.stdout,
              "safe.directory '*' in the global git config opens the foreign-owned workspace")
        (home / ".gitconfig").unlink()

        # 1. A push to main: run, record, results branch, dashboard.
        main_sha = tracer_repo.git(workspace, "-c", "safe.directory=*", "rev-parse", "HEAD")
        runner, steps = job(tmp / "job1", workspace, forge, "push", {"ref": "refs/heads/main"},
                            {"sha": main_sha, "ref_name": "main", "head_ref": "", "base_ref": ""},
                            bin_dir, source, env, rounds=2)
        check(not runner.failed and steps["measure"]["outputs"].get("exit-code") == "0",
              "push: the action ran raygate run and passed", runner)
        check(str(workspace) in (home / ".gitconfig").read_text(),
              "push: the action added the workspace to git's safe.directory")
        files = tracer_repo.git(origin, "ls-tree", "-r", "--name-only", "raygate-results").split()
        check("index.html" in files and sum(f.startswith("results/") and f.endswith(".json") for f in files) == 1,
              f"push: origin's raygate-results branch holds the document and the dashboard ({files})", runner)
        dashboard = tracer_repo.git(origin, "show", "raygate-results:index.html")
        check("<svg" in dashboard and "tetra" in dashboard, "push: the dashboard plots the scenes")
        artifact = tmp / "job1" / "artifacts" / "raygate-report"
        check(all((artifact / f).is_file() for f in ("results.json", "report.html", "junit.xml", "verdict.json")),
              "push: the artifact holds results.json, report.html, junit.xml, verdict.json", runner)
        check("tetra" in runner.summary, "push: the report is in the job summary", runner)

        # 2. A pull request from branch slower: compare, regression, one comment.
        tracer_repo.git(workspace, "-c", "safe.directory=*", "checkout", "--quiet", "slower")
        chown_tree(workspace, NOBODY)
        head_sha = tracer_repo.git(workspace, "-c", "safe.directory=*", "rev-parse", "HEAD")
        pr_event = {"number": 7, "pull_request": {"number": 7, "head": {"ref": "slower", "sha": head_sha},
                                                   "base": {"ref": "main", "sha": main_sha}}}
        pr_github = {"sha": head_sha, "ref_name": "7/merge", "head_ref": "slower", "base_ref": "main"}
        (tmp / "job2").mkdir()
        os.rename(tmp / "job1" / "actions-cache", tmp / "job2" / "actions-cache")  # the cache outlives jobs
        # Twelve rounds: the fewest from which compare draws a verdict on one scene (its confidence
        # sequence at the family's 1%, docs/statistics.md §6a).
        runner, steps = job(tmp / "job2", workspace, forge, "pull_request", pr_event, pr_github,
                            bin_dir, source, env, rounds=12)
        log = "\n".join(runner.log)
        check("cache: restored raygate-tracer-Linux--" in log,
              "pull request: the tracer builds saved by the push were restored", runner)
        check("results-branch: 1 documents from origin raygate-results" in log,
              "pull request: the history was imported from the results branch", runner)
        check(runner.failed and steps["measure"]["outputs"].get("exit-code") == "1"
              and "raygate: regression (exit 1)" in log,
              "pull request: compare found the slowdown and the gate failed with exit 1", runner)
        report_dir = pathlib.Path(steps["measure"]["outputs"]["report-dir"])
        check((report_dir / "pr-number").read_text().strip() == "7", "pull request: pr-number kept for workflow_run")
        comments = forge.comments.get("7", [])
        check(len(comments) == 1 and comments[0]["body"].startswith(MARKER) and "REGRESSED" in comments[0]["body"],
              "pull request: one comment with the marker and the verdict", runner)
        first_id = comments[0]["id"]

        # 3. The same pull request again (one round: no verdict, a pass): the comment is edited.
        (tmp / "job3").mkdir()
        os.rename(tmp / "job2" / "actions-cache", tmp / "job3" / "actions-cache")
        runner, _ = job(tmp / "job3", workspace, forge, "pull_request", pr_event, pr_github,
                        bin_dir, source, env, rounds=1)
        comments = forge.comments.get("7", [])
        edit = ("PATCH", f"/repos/octo/tracer/issues/comments/{first_id}")
        check(len(comments) == 1 and comments[0]["id"] == first_id
              and "REGRESSED" not in comments[0]["body"] and edit in forge.requests,
              "pull request, second push: the same comment was updated in place", runner)
        print(json.dumps({"requests": forge.requests}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
