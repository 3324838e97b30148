#!/usr/bin/env python3
"""ci/pr-comment against a local stand-in of the GitHub and GitLab APIs (fake_forge.py): the
raygate comment is found past the first page of 100 and edited, not duplicated; a thread without
one gets one; a PR number that is not digits (it may come from a fork's artifact) is refused
before any request; a refused token fails the command.

usage: pr_comment_test.py RAYGATE_SOURCE_DIR
"""
import os
import pathlib
import subprocess
import sys
import tempfile

import fake_forge

MARKER = "<!-- raygate-report -->"


def main():
    script = pathlib.Path(sys.argv[1]).resolve() / "ci" / "pr-comment"
    with tempfile.TemporaryDirectory(prefix="raygate-comment-") as tmp, fake_forge.Forge("t0ken") as forge:
        report = pathlib.Path(tmp) / "report.md"
        report.write_text("| scene | verdict |\n|---|---|\n| tetra | REGRESSED |\n")
        github = dict(os.environ, GH_TOKEN="t0ken", GITHUB_REPOSITORY="octo/tracer", GITHUB_API_URL=forge.url)
        gitlab = dict(os.environ, RAYGATE_NOTE_TOKEN="t0ken", CI_PROJECT_ID="42",
                      CI_API_V4_URL=f"{forge.url}/api/v4")

        def post(env, forge_name, number, token=None):
            if token:
                env = dict(env, GH_TOKEN=token, RAYGATE_NOTE_TOKEN=token)
            return subprocess.run([str(script), forge_name, str(report), number], env=env,
                                  capture_output=True, text=True, timeout=60)

        # 150 people's comments, the raygate one on page 2.
        forge.comments["3"] = [{"id": i, "body": f"comment {i}"} for i in range(1, 151)]
        forge.comments["3"][120]["body"] = MARKER + "\nold report"
        r = post(github, "github", "3")
        assert r.returncode == 0 and "updated comment 121" in r.stdout, r.stdout + r.stderr
        assert len(forge.comments["3"]) == 150 and "REGRESSED" in forge.comments["3"][120]["body"]
        print("ok   github: the marked comment on page 2 was edited, none added")

        r = post(gitlab, "gitlab", "9")
        assert r.returncode == 0 and len(forge.comments["9"]) == 1, r.stdout + r.stderr
        assert forge.comments["9"][0]["body"].startswith(MARKER)
        r = post(gitlab, "gitlab", "9")
        assert r.returncode == 0 and len(forge.comments["9"]) == 1 and "updated" in r.stdout, r.stdout
        print("ok   gitlab: one note posted, then edited in place")

        before = len(forge.requests)
        r = post(github, "github", "3; rm -rf /")
        assert r.returncode == 2 and len(forge.requests) == before, r.stderr
        print("ok   a PR number that is not digits is refused before any request")

        r = post(github, "github", "4", token="wrong")
        assert r.returncode != 0 and "4" not in forge.comments, r.stdout + r.stderr
        print("ok   a refused token fails the command")
    return 0


if __name__ == "__main__":
    sys.exit(main())
