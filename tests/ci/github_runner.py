"""A local stand-in for the GitHub Actions runner, enough to execute a composite action
(ci/github/action.yml) for real: what the runner does with the action's steps, not a mock of
what the steps do.

It reads action.yml, evaluates `${{ }}` expressions (contexts inputs, github, runner, steps, env;
functions always, success, failure, cancelled, startsWith, endsWith, contains, hashFiles;
operators ! == != && || and parentheses) in `if:`, `env:`, `with:` and `run:`, and runs each
`run:` step with its shell as the runner does (bash: `bash --noprofile --norc -eo pipefail
FILE`), in GITHUB_WORKSPACE, with a fresh GITHUB_OUTPUT file per step (`name=value` and
`name<<DELIMITER` forms), GITHUB_ENV carried to the later steps, GITHUB_STEP_SUMMARY,
GITHUB_EVENT_PATH and the other variables the runner sets. A step that fails skips the later
steps whose `if:` does not ask for always()/failure().

The `uses:` steps are the two marketplace actions the composite uses, emulated on the local file
system with their documented semantics: actions/cache (restore by exact key, else the newest
entry matching a restore-keys prefix; save at the end of the job unless the key was hit) and
actions/upload-artifact (a copy of the path under the artifact's name). Anything else is an
error, so a new `uses:` in the action cannot pass unnoticed.
"""
import hashlib
import json
import os
import pathlib
import re
import shutil
import subprocess
import time

import yaml

EXPRESSION = re.compile(r'\$\{\{(.*?)\}\}', re.S)
TOKEN = re.compile(r"\s*(?:(?P<str>'(?:[^']|'')*')|(?P<num>\d+(?:\.\d+)?)|(?P<op>==|!=|&&|\|\||[!(),])"
                   r"|(?P<name>[A-Za-z_][A-Za-z0-9_.\-]*))")


def truthy(value):
    return value not in (None, False, 0, "", [], {})


class Expression:
    """A recursive-descent evaluator of GitHub's expression syntax (the subset actions use)."""

    def __init__(self, text, contexts, functions):
        self.tokens = []
        pos = 0
        text = text.strip()
        while pos < len(text):
            m = TOKEN.match(text, pos)
            if not m or m.end() == pos:
                raise ValueError(f"cannot parse expression at {text[pos:]!r}")
            kind = m.lastgroup
            self.tokens.append((kind, m.group(kind)))
            pos = m.end()
            while pos < len(text) and text[pos].isspace():
                pos += 1
        self.at = 0
        self.contexts = contexts
        self.functions = functions

    def peek(self):
        return self.tokens[self.at] if self.at < len(self.tokens) else (None, None)

    def take(self, value=None):
        token = self.peek()
        if value is not None and token[1] != value:
            raise ValueError(f"expected {value!r}, got {token[1]!r}")
        self.at += 1
        return token

    def evaluate(self):
        value = self.or_()
        if self.at != len(self.tokens):
            raise ValueError(f"trailing tokens {self.tokens[self.at:]}")
        return value

    def or_(self):
        value = self.and_()
        while self.peek()[1] == "||":
            self.take()
            right = self.and_()
            value = value if truthy(value) else right
        return value

    def and_(self):
        value = self.compare()
        while self.peek()[1] == "&&":
            self.take()
            right = self.compare()
            value = right if truthy(value) else value
        return value

    def compare(self):
        value = self.unary()
        while self.peek()[1] in ("==", "!="):
            op = self.take()[1]
            right = self.unary()
            same = str(value).lower() == str(right).lower() if isinstance(value, str) and isinstance(right, str) \
                else value == right
            value = same if op == "==" else not same
        return value

    def unary(self):
        if self.peek()[1] == "!":
            self.take()
            return not truthy(self.unary())
        return self.primary()

    def primary(self):
        kind, text = self.take()
        if text == "(":
            value = self.or_()
            self.take(")")
            return value
        if kind == "str":
            return text[1:-1].replace("''", "'")
        if kind == "num":
            return float(text) if "." in text else int(text)
        if kind == "name":
            if self.peek()[1] == "(":
                self.take("(")
                args = []
                while self.peek()[1] != ")":
                    args.append(self.or_())
                    if self.peek()[1] == ",":
                        self.take()
                self.take(")")
                return self.functions[text](*args)
            if text in ("true", "false"):
                return text == "true"
            if text == "null":
                return None
            return self.lookup(text)
        raise ValueError(f"unexpected token {text!r}")

    def lookup(self, dotted):
        parts = dotted.split(".")
        value = self.contexts.get(parts[0])
        for part in parts[1:]:
            value = value.get(part) if isinstance(value, dict) else None
        return value


def to_text(value):
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def parse_command_file(path):
    """GITHUB_OUTPUT / GITHUB_ENV: `name=value` lines and `name<<DELIMITER` blocks."""
    values = {}
    if not path.exists():
        return values
    lines = path.read_text().split("\n")
    i = 0
    while i < len(lines):
        line = lines[i]
        if "<<" in line and ("=" not in line or line.index("<<") < line.index("=")):
            name, delimiter = line.split("<<", 1)
            body = []
            i += 1
            while i < len(lines) and lines[i] != delimiter:
                body.append(lines[i])
                i += 1
            values[name] = "\n".join(body)
        elif "=" in line:
            name, value = line.split("=", 1)
            values[name] = value
        i += 1
    return values


class Runner:
    """One job on one simulated runner: `run_action` executes a composite action in it."""

    def __init__(self, root, workspace, event_name, event, github, env):
        self.root = pathlib.Path(root)
        self.workspace = pathlib.Path(workspace)
        self.temp = self.root / "runner-temp"
        self.cache_store = self.root / "actions-cache"
        self.artifacts = self.root / "artifacts"
        for d in (self.temp, self.cache_store, self.artifacts):
            d.mkdir(parents=True, exist_ok=True)
        self.event_path = self.temp / "event.json"
        self.event_path.write_text(json.dumps(event))
        self.github = dict(github, event_name=event_name, event=event, workspace=str(self.workspace))
        self.env = dict(env)
        self.summary = ""
        self.log = []
        self.failed = False
        self.post_steps = []
        self.durations = []   # (step name, seconds)

    def run_action(self, action_dir, with_inputs):
        action_dir = pathlib.Path(action_dir)
        action = yaml.safe_load((action_dir / "action.yml").read_text())
        assert action["runs"]["using"] == "composite", "only composite actions"
        inputs = {name: to_text(spec.get("default", "")) for name, spec in action.get("inputs", {}).items()}
        unknown = set(with_inputs) - set(inputs)
        assert not unknown, f"inputs the action does not declare: {unknown}"
        inputs.update(with_inputs)
        steps_context = {}
        for index, step in enumerate(action["runs"]["steps"]):
            self.run_step(index, step, inputs, steps_context, action_dir)
        for post in reversed(self.post_steps):
            post()
        return steps_context

    def contexts(self, inputs, steps_context):
        return {"inputs": inputs, "github": self.github, "steps": steps_context, "env": self.env,
                "runner": {"os": "Linux", "temp": str(self.temp), "arch": "X64"}}

    def functions(self):
        return {
            "always": lambda: True,
            "success": lambda: not self.failed,
            "failure": lambda: self.failed,
            "cancelled": lambda: False,
            "startsWith": lambda a, b: to_text(a).lower().startswith(to_text(b).lower()),
            "endsWith": lambda a, b: to_text(a).lower().endswith(to_text(b).lower()),
            "contains": lambda a, b: to_text(b).lower() in to_text(a).lower(),
            "hashFiles": self.hash_files,
        }

    def hash_files(self, *patterns):
        files = sorted(p for pattern in patterns for p in self.workspace.glob(to_text(pattern)) if p.is_file())
        if not files:
            return ""
        digest = hashlib.sha256()
        for f in files:
            digest.update(hashlib.sha256(f.read_bytes()).digest())
        return digest.hexdigest()

    def evaluate(self, text, inputs, steps_context):
        return Expression(text, self.contexts(inputs, steps_context), self.functions()).evaluate()

    def expand(self, text, inputs, steps_context):
        return EXPRESSION.sub(lambda m: to_text(self.evaluate(m.group(1), inputs, steps_context)), to_text(text))

    def should_run(self, step, inputs, steps_context):
        condition = step.get("if")
        if condition is None:
            return not self.failed
        condition = to_text(condition).strip()
        m = EXPRESSION.fullmatch(condition)
        condition = m.group(1) if m else condition
        status_functions = ("always()", "success()", "failure()", "cancelled()")
        if not any(f in condition for f in status_functions):
            condition = f"success() && ({condition})"   # the runner's implicit success()
        return truthy(self.evaluate(condition, inputs, steps_context))

    def run_step(self, index, step, inputs, steps_context, action_dir):
        name = step.get("name", step.get("uses", f"step {index}"))
        step_id = step.get("id", f"__step{index}")
        if not self.should_run(step, inputs, steps_context):
            self.log.append(f"skipped: {name}")
            steps_context[step_id] = {"outputs": {}, "outcome": "skipped", "conclusion": "skipped"}
            return
        self.log.append(f"run: {name}")
        started = time.monotonic()
        if "run" in step:
            outputs, ok = self.run_shell(step, inputs, steps_context, action_dir)
        else:
            outputs, ok = self.run_uses(step, inputs, steps_context)
        self.durations.append((name, time.monotonic() - started))
        outcome = "success" if ok else "failure"
        steps_context[step_id] = {"outputs": outputs, "outcome": outcome, "conclusion": outcome}
        if not ok:
            self.failed = True

    def run_shell(self, step, inputs, steps_context, action_dir):
        assert step.get("shell") == "bash", f"composite run steps need shell: bash ({step.get('name')})"
        script = self.temp / "step.sh"
        script.write_text(self.expand(step["run"], inputs, steps_context))
        files = {k: self.temp / f"{k.lower()}-{time.monotonic_ns()}" for k in ("GITHUB_OUTPUT", "GITHUB_ENV")}
        summary = self.temp / f"summary-{time.monotonic_ns()}"
        for f in list(files.values()) + [summary]:
            f.write_text("")
        env = dict(os.environ)
        env.update(self.env)
        env.update({
            "GITHUB_ACTIONS": "true", "CI": "true", "GITHUB_WORKSPACE": str(self.workspace),
            "GITHUB_ACTION_PATH": str(action_dir), "RUNNER_TEMP": str(self.temp), "RUNNER_OS": "Linux",
            "GITHUB_EVENT_PATH": str(self.event_path), "GITHUB_EVENT_NAME": self.github["event_name"],
            "GITHUB_REPOSITORY": self.github["repository"], "GITHUB_SHA": self.github["sha"],
            "GITHUB_REF_NAME": self.github["ref_name"], "GITHUB_HEAD_REF": self.github.get("head_ref", ""),
            "GITHUB_BASE_REF": self.github.get("base_ref", ""), "GITHUB_API_URL": self.github["api_url"],
            "GITHUB_STEP_SUMMARY": str(summary), **{k: str(v) for k, v in files.items()}})
        for key, value in step.get("env", {}).items():
            env[key] = self.expand(value, inputs, steps_context)
        r = subprocess.run(["bash", "--noprofile", "--norc", "-eo", "pipefail", str(script)],
                           cwd=self.workspace, env=env, capture_output=True, text=True, timeout=600)
        self.log.append(r.stdout + r.stderr)
        self.env.update(parse_command_file(files["GITHUB_ENV"]))
        self.summary += summary.read_text()
        return parse_command_file(files["GITHUB_OUTPUT"]), r.returncode == 0

    def run_uses(self, step, inputs, steps_context):
        uses = step["uses"]
        with_ = {k: self.expand(v, inputs, steps_context) for k, v in step.get("with", {}).items()}
        if uses.startswith("actions/cache@"):
            return self.cache(with_), True
        if uses.startswith("actions/upload-artifact@"):
            return self.upload(with_), True
        raise AssertionError(f"the simulated runner does not emulate {uses}")

    def paths(self, text):
        return [self.workspace / p.strip() for p in text.splitlines() if p.strip()]

    def cache(self, with_):
        key = with_["key"]
        paths = self.paths(with_["path"])
        hit = self.cache_store / key
        restored = hit if hit.exists() else None
        if restored is None:
            for prefix in [p.strip() for p in with_.get("restore-keys", "").splitlines() if p.strip()]:
                matches = sorted((e for e in self.cache_store.iterdir() if e.name.startswith(prefix)),
                                 key=lambda e: e.stat().st_mtime, reverse=True)
                if matches:
                    restored = matches[0]
                    break
        if restored is not None:
            for i, path in enumerate(paths):
                saved = restored / str(i)
                if saved.exists():
                    shutil.rmtree(path, ignore_errors=True)
                    shutil.copytree(saved, path, symlinks=True)
            self.log.append(f"cache: restored {restored.name} for key {key}")
        exact = restored is not None and restored.name == key

        def save():
            if exact or hit.exists():
                return
            for i, path in enumerate(paths):
                if path.exists():
                    shutil.copytree(path, hit / str(i), symlinks=True)
            hit.mkdir(parents=True, exist_ok=True)
            self.log.append(f"cache: saved {key}")
        self.post_steps.append(save)
        return {"cache-hit": "true" if exact else "false"}

    def upload(self, with_):
        target = self.artifacts / with_["name"]
        for path in self.paths(with_["path"]):
            if path.is_dir():
                shutil.copytree(path, target, dirs_exist_ok=True)
            elif path.exists():
                target.mkdir(parents=True, exist_ok=True)
                shutil.copy2(path, target)
        return {}
