#!/usr/bin/env python3
"""Checks raygate's CI templates (ci/github/, ci/gitlab/), the main job (ci/main-job) and the
results branch script (ci/results-branch):

1. every YAML template parses (python3-yaml) and has the structure its platform needs: the
   composite action `runs.using: composite`, the reusable workflow `on.workflow_call`, the
   example caller `on.pull_request` + `on.push` and a job that uses the action, the GitLab
   template its jobs with `script` and `rules` extending an existing hidden job, the GitLab
   example an `include`;
2. every `raygate <subcommand> ...` the templates run names a real subcommand, and every `--flag`
   on it is one that subcommand accepts, by the built raygate's own `--help`. Flags passed
   through bash arrays (`"${reports[@]}"`) are looked up in the array's assignments.

A self-check first feeds the checker a template with a flag raygate does not have and demands
an error, so the test cannot pass by finding nothing.

usage: ci_templates_test.py RAYGATE_EXECUTABLE RAYGATE_SOURCE_DIR
"""
import pathlib
import re
import subprocess
import sys

import yaml

# `raygate` as a command: $RAYGATE, "$RAYGATE", ${RAYGATE}, "$raygate", .../bin/raygate, then the
# subcommand (and maybe its own subcommand: `golden verify`).
INVOCATION = re.compile(
    r'''(?:"?\$\{?(?:RAYGATE|raygate)\}?"?|\S*/bin/raygate)[ \t]+([a-z][a-z-]*)((?:[ \t]+[a-z][a-z-]*)?)(.*)''')
FLAG = re.compile(r'(?<![\w-])(--[a-z0-9][a-z0-9-]*)')
ARRAY = re.compile(r'\b([A-Za-z_][A-Za-z0-9_]*)\+?=\((.*?)\)', re.S)
ARRAY_USE = re.compile(r'\$\{([A-Za-z_][A-Za-z0-9_]*)\[@\]\}')


class Raygate:
    """What the built raygate says it accepts, from its --help pages (cached)."""

    def __init__(self, exe):
        self.exe = exe
        self.pages = {}

    def help(self, words):
        key = tuple(words)
        if key not in self.pages:
            r = subprocess.run([self.exe, *words, "--help"], capture_output=True, text=True, timeout=30)
            self.pages[key] = (r.returncode, r.stdout + r.stderr)
        return self.pages[key]

    def subcommands(self, words):
        code, text = self.help(words)
        parts = re.split(r'^subcommands:\s*$', text, maxsplit=1, flags=re.M | re.I)  # CLI11's heading
        if code != 0 or len(parts) < 2:
            return set()
        return set(re.findall(r'^\s{2}([a-z][a-z-]*)\b', parts[1], re.M))

    def flags(self, words):
        code, text = self.help(words)
        return set(FLAG.findall(text)) if code == 0 else set()


def shell_texts(node):
    """Every string of a YAML document: run:, script:, before_script: and the rest alike."""
    if isinstance(node, str):
        yield node
    elif isinstance(node, dict):
        for value in node.values():
            yield from shell_texts(value)
    elif isinstance(node, list):
        for value in node:
            yield from shell_texts(value)


def join_lines(text):
    return re.sub(r'\\\n\s*', ' ', text)  # line continuations


def bash_arrays(texts):
    """name -> flags of every bash array assigned in the texts (`a=(...)`, `a+=(...)`). GitLab
    runs before_script and script in one shell, so a job's arrays are shared by all its texts."""
    arrays = {}
    for text in texts:
        for name, body in ARRAY.findall(join_lines(text)):
            arrays.setdefault(name, []).extend(FLAG.findall(body))
    return arrays


def invocations(text, arrays):
    """(subcommand words, flags) of each raygate command in a shell text."""
    found = []
    for line in join_lines(text).splitlines():
        for m in INVOCATION.finditer(line):
            words = [m.group(1)] + m.group(2).split()
            rest = m.group(3)
            flags = FLAG.findall(rest)
            for name in ARRAY_USE.findall(rest):
                flags.extend(arrays.get(name, []))
            found.append((words, flags))
    return found


def check_invocation(raygate, words, flags, where):
    """Problems of one invocation: an unknown subcommand, flags the subcommand does not take."""
    top = raygate.subcommands([])
    if words[0] not in top:
        return [f"{where}: 'raygate {words[0]}' is not a raygate subcommand (have: {', '.join(sorted(top))})"]
    command = [words[0]]
    if len(words) > 1 and words[1] in raygate.subcommands(command):
        command.append(words[1])
    accepted = raygate.flags(command)
    return [f"{where}: 'raygate {' '.join(command)}' has no option {flag}"
            for flag in flags if flag not in accepted]


def check_commands(raygate, name, texts):
    texts = list(texts)
    arrays = bash_arrays(texts)
    problems, count = [], 0
    for text in texts:
        for words, flags in invocations(text, arrays):
            count += 1
            problems += check_invocation(raygate, words, flags, name)
    return problems, count


def workflow_on(doc):
    # YAML 1.1 reads a bare `on` key as the boolean true.
    return doc.get("on", doc.get(True)) or {}


def check_structure(root):
    problems = []

    def need(condition, what):
        if not condition:
            problems.append(what)

    gh = root / "ci" / "github"
    action = yaml.safe_load((gh / "action.yml").read_text())
    need(action.get("runs", {}).get("using") == "composite", "action.yml: runs.using must be composite")
    need(action.get("inputs", {}).get("adapter", {}).get("required") is True,
         "action.yml: input 'adapter' must be required")
    steps = action.get("runs", {}).get("steps", [])
    need(all("shell" in s for s in steps if "run" in s), "action.yml: every run step needs shell: (composite)")
    uses = [s.get("uses", "") for s in steps]
    need(any(u.startswith("actions/upload-artifact@") for u in uses), "action.yml: no artifact upload")
    # A `${{ }}` spliced into a script's text runs what it holds (a branch named $(...) is a valid
    # git name): GitHub's values reach scripts through env: only (a sweep found one that did not).
    for workflow in ("action.yml", "raygate.yml", "comment-from-fork.yml", "example-caller.yml"):
        doc = yaml.safe_load((gh / workflow).read_text())
        runs = [s for s in doc.get("runs", {}).get("steps", [])]
        runs += [s for job in doc.get("jobs", {}).values() for s in job.get("steps", [])]
        for step in runs:
            need("${{" not in step.get("run", ""),
                 f"{workflow}: step '{step.get('name', '?')}' splices ${{{{ }}}} into its script; pass it in env:")

    reusable = yaml.safe_load((gh / "raygate.yml").read_text())
    call = workflow_on(reusable).get("workflow_call", None)
    need(isinstance(call, dict) and "adapter" in call.get("inputs", {}),
         "raygate.yml: on.workflow_call with an 'adapter' input expected")
    job_steps = [s for job in reusable.get("jobs", {}).values() for s in job.get("steps", [])]
    need(any(s.get("with", {}).get("fetch-depth") == 0 for s in job_steps),
         "raygate.yml: the tracer checkout needs fetch-depth: 0")

    caller = yaml.safe_load((gh / "example-caller.yml").read_text())
    on = workflow_on(caller)
    need("pull_request" in on and "push" in on, "example-caller.yml: on pull_request and push expected")
    caller_steps = [s for job in caller.get("jobs", {}).values() for s in job.get("steps", [])]
    need(any("/ci/github@" in s.get("uses", "") for s in caller_steps),
         "example-caller.yml: a step must use the raygate action (OWNER/raygate/ci/github@REF)")
    need(any(s.get("with", {}).get("fetch-depth") == 0 for s in caller_steps),
         "example-caller.yml: checkout needs fetch-depth: 0")

    fork = yaml.safe_load((gh / "comment-from-fork.yml").read_text())
    need("workflow_run" in workflow_on(fork), "comment-from-fork.yml: on.workflow_run expected")
    fork_runs = [s.get("run", "") for job in fork.get("jobs", {}).values() for s in job.get("steps", [])]
    need(any("ci/pr-comment github" in r for r in fork_runs), "comment-from-fork.yml: must post with ci/pr-comment")

    gl = root / "ci" / "gitlab"
    template = yaml.safe_load((gl / "raygate.gitlab-ci.yml").read_text())
    need("RAYGATE_ADAPTER" in template.get("variables", {}), "raygate.gitlab-ci.yml: variable RAYGATE_ADAPTER")
    jobs = {k: v for k, v in template.items() if isinstance(v, dict) and k not in ("variables", "default")}
    visible = {k: v for k, v in jobs.items() if not k.startswith(".")}
    need({"raygate:compare", "raygate:record"} <= set(visible),
         "raygate.gitlab-ci.yml: jobs raygate:compare and raygate:record expected")
    for name, job in visible.items():
        need("script" in job and "rules" in job, f"raygate.gitlab-ci.yml: {name} needs script and rules")
        parent = job.get("extends")
        need(parent is None or parent in jobs, f"raygate.gitlab-ci.yml: {name} extends unknown {parent}")
    base = jobs.get(".raygate", {})
    need(base.get("variables", {}).get("GIT_DEPTH") == "0", "raygate.gitlab-ci.yml: GIT_DEPTH must be 0")
    need("junit" in base.get("artifacts", {}).get("reports", {}), "raygate.gitlab-ci.yml: junit report artifact")
    example = yaml.safe_load((gl / "example.gitlab-ci.yml").read_text())
    need(any(i.get("file") == "ci/gitlab/raygate.gitlab-ci.yml" or "raygate.gitlab-ci.yml" in i.get("remote", "")
             for i in example.get("include", [])), "example.gitlab-ci.yml: must include raygate.gitlab-ci.yml")
    need(bool(example.get("variables", {}).get("RAYGATE_ADAPTER")), "example.gitlab-ci.yml: set RAYGATE_ADAPTER")
    return problems


def self_check(raygate):
    """The checker must catch a made-up flag and a made-up subcommand, and pass a real line."""
    bad = 'x=(--report md:a)\n"$RAYGATE" compare --repo . --base-branch main \\\n  --no-such-flag "${x[@]}"\n'
    problems, count = check_commands(raygate, "self-check", [bad])
    assert count == 1 and len(problems) == 1 and "--no-such-flag" in problems[0], problems
    problems, _ = check_commands(raygate, "self-check", ['$RAYGATE frobnicate --repo .'])
    assert len(problems) == 1 and "frobnicate" in problems[0], problems
    problems, count = check_commands(raygate, "self-check", ['out/release/bin/raygate golden verify --suite ci'])
    assert count == 1 and not problems, problems


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    raygate = Raygate(sys.argv[1])
    root = pathlib.Path(sys.argv[2])
    self_check(raygate)
    problems = check_structure(root)
    total = 0
    templates = sorted((root / "ci" / "github").glob("*.yml")) + sorted((root / "ci" / "gitlab").glob("*.yml"))
    for path in templates:
        found, count = check_commands(raygate, str(path.relative_to(root)), shell_texts(yaml.safe_load(path.read_text())))
        problems += found
        total += count
    for script in ("main-job", "results-branch"):
        found, count = check_commands(raygate, f"ci/{script}", [(root / "ci" / script).read_text()])
        problems += found
        total += count
    for problem in problems:
        print("FAIL " + problem)
    if total < 4:
        problems.append(f"only {total} raygate invocations found in the templates: the extraction is broken")
        print("FAIL " + problems[-1])
    print(f"{len(templates)} templates, {total} raygate invocations checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
