#!/usr/bin/env python3
"""Writes the seed inputs of the fuzz corpus (tests/fuzz/corpus/<reader>/seed-*): valid inputs
of each reader and near misses of them (one field wrong), so the fuzzer starts from every shape
the reader knows. Inputs the fuzzer found are kept beside them under other names (found-*).
Run from the repository root: bench/fuzz/make_seeds.py"""
import copy
import json
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "fuzz" / "corpus"


def write(reader, name, text):
    folder = CORPUS / reader
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"seed-{name}").write_bytes(text.encode() if isinstance(text, str) else text)


def nff_seeds():
    for f in sorted((ROOT / "baseline" / "examples").glob("*.nff")):
        write("nff", f.stem + ".nff", f.read_text())
    view = "v\nfrom 0 -5 1\nat 0 0 0\nup 0 0 1\nangle 45\nhither 0.01\nresolution 32 24\n"
    mat = "f 0.8 0.2 0.2 0.7 0.3 10 0 1\n"
    bodies = {
        "sphere": "s 0 0 0 1\n",
        "cone": "c 0 0 0 1 0 0 2 0.5\n",
        "cylinder": "c 0 0 0 1 0 0 2 1\n",
        "polygon": "p 3\n0 0 0\n1 0 0\n0 1 0\n",
        "patch": "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n",
        "light-rgb": "l 1 2 3 0.5 0.5 0.5\ns 0 0 0 1\n",
        "background": "b 0.1 0.2 0.3\ns 0 0 0 1\n",
        "comment": "# a comment\ns 0 0 0 1 # trailing\n",
        "many": "".join(f"s {i} {i % 3} {i % 5} 0.5\n" for i in range(12)),
    }
    for name, body in bodies.items():
        write("nff", name + ".nff", view + "l 1 -4 5\n" + mat + body)
    broken = {
        "no-view": "s 0 0 0 1\n",
        "bad-number": view + mat + "s 0 0 zero 1\n",
        "huge-resolution": view.replace("32 24", "16385 1") + mat + "s 0 0 0 1\n",
        "polygon-short": view + mat + "p 5\n0 0 0\n1 0 0\n",
        "nan": view + mat + "s nan 0 0 1\n",
        "exponent": view + mat + "s 1e308 1e-308 -1e400 1\n",
        "nul": view + mat + "s 0 0\x00 0 1\n",
        "empty": "",
    }
    for name, text in broken.items():
        write("nff", name + ".nff", text)


def adapter_seeds():
    for f in sorted((ROOT / "adapters").glob("*.json")):
        write("adapter", f.name, f.read_text())
    base = json.loads((ROOT / "adapters" / "make-nff.json").read_text())
    variants = {
        "stdin": {"stdin": "{scene}", "run": ["{build}/tracer", "-o", "{image}"]},
        "env": {"env": {"OMP_NUM_THREADS": "{threads}", "SCENE": "{scene}"}},
        "reported": {"timing": {"source": "reported", "regex": "time: ([0-9.]+) s"}},
        "workdir": {"image": "{workdir}/out.png", "cwd": "{workdir}"},
        "nul": {"run": ["{build}/tracer", "{scene}\u0000x", "-o", "{image}"]},
        "typo": {"timeout_s": {"run": 0}},
        "placeholder": {"run": ["{build}/tracer", "{scen}", "-o", "{image}"]},
        "source-dir": {"source_dir": "../outside"},
        "threads": {"threads": 99999999999},
    }
    for name, change in variants.items():
        doc = copy.deepcopy(base)
        doc.update(change)
        write("adapter", name + ".json", json.dumps(doc, indent=1))
    write("adapter", "duplicate.json", '{"name": "a", "name": "b"}')
    write("adapter", "big-number.json", '{"name": "t", "threads": 1e400}')


def suite_seeds():
    for f in sorted((ROOT / "scenes" / "suites").glob("*.json")):
        write("suite", f.name, f.read_text())
    write("suite", "one.json", json.dumps({"name": "one", "scenes": [{"scene": "balls"}]}))
    write("suite", "sized.json", json.dumps(
        {"name": "s", "sampling": "corners",
         "scenes": [{"id": "b", "scene": "balls", "size": 2, "resolution": [16, 16]}]}))
    write("suite", "dup.json", json.dumps(
        {"scenes": [{"id": "a", "scene": "balls"}, {"id": "a", "scene": "gears"}]}))
    write("suite", "bad-size.json", json.dumps({"scenes": [{"scene": "balls", "size": 0}]}))
    write("suite", "bad-id.json", json.dumps({"scenes": [{"id": "../x", "scene": "balls"}]}))
    more = {
        "all-scenes": {"name": "all", "scenes": [{"scene": n} for n in
                       ["balls", "gears", "mount", "rings", "teapot", "tetra", "tree",
                        "lattice", "shells", "jacks", "sombrero", "sample", "nurbtst"]]},
        "desc": {"name": "d", "description": "x", "scenes": [{"scene": "tree", "size": 3}]},
        "bad-sampling": {"sampling": "random", "scenes": [{"scene": "balls"}]},
        "unknown-scene": {"scenes": [{"scene": "ballz"}]},
        "unknown-key": {"scenes": [{"scene": "balls", "colour": 1}]},
        "res-float": {"scenes": [{"scene": "balls", "resolution": [1.5, 2]}]},
        "res-three": {"scenes": [{"scene": "balls", "resolution": [1, 2, 3]}]},
        "empty-scenes": {"scenes": []},
        "name-path": {"name": "../up", "scenes": [{"scene": "balls"}]},
        "size-max": {"scenes": [{"scene": "teapot", "size": 99}]},
        "id-number": {"scenes": [{"scene": "balls", "id": 7}]},
    }
    for name, doc in more.items():
        write("suite", name + ".json", json.dumps(doc))
    write("suite", "huge-res.json",
          json.dumps({"scenes": [{"scene": "balls", "resolution": [99999999999, 1]}]}))


def policy_seeds():
    policy = {
        "max_slowdown": 0.03, "significance": 0.05, "family_significance": 0.01,
        "image": {"fail": 0.004, "failpercent": 0.02, "hardfail": 1.0, "warn": 0.004},
        "fail_on_inconclusive": False, "max_exponent_increase": 0.1,
        "scenes": {"mount": {"max_slowdown": 0.06, "reason": "terrain"},
                   "gears": {"image": {"failpercent": 0.5}, "reason": "noise"}},
    }
    write("policy", "full.json", json.dumps(policy, indent=1))
    write("policy", "empty.json", "{}")
    write("policy", "slowdown.json", '{"max_slowdown": 0.1}')
    write("policy", "negative.json", '{"max_slowdown": -1}')
    write("policy", "significance.json", '{"significance": 1.5}')
    write("policy", "duplicate.json", '{"max_slowdown": 0.03, "max_slowdown": 5}')
    write("policy", "big.json", '{"max_slowdown": 1e400}')
    write("policy", "scene-typo.json", '{"scenes": {"x": {"max_slowdow": 1}}}')
    write("policy", "array.json", "[1, 2, 3]")
    more = {
        "family": {"family_significance": 0.001},
        "inconclusive": {"fail_on_inconclusive": True},
        "exponent": {"max_exponent_increase": 0.5},
        "image-only": {"image": {"fail": 0.1, "warn": 0.01}},
        "hardfail": {"image": {"hardfail": 2.0, "failpercent": 100}},
        "scene-reason": {"scenes": {"balls": {"max_slowdown": 0.2, "reason": "why"}}},
        "scene-empty-reason": {"scenes": {"balls": {"max_slowdown": 0.2, "reason": ""}}},
        "scene-image": {"scenes": {"tree": {"image": {"warn": 0.5}, "reason": "leaves"}}},
        "scene-significance": {"scenes": {"tree": {"significance": 0.2, "reason": "r"}}},
        "tiny-significance": {"significance": 0.00001},
        "string-number": {"max_slowdown": "0.03"},
        "nested-wrong": {"image": [0.1]},
        "unknown": {"colour": "red"},
        "scenes-array": {"scenes": ["balls"]},
    }
    for name, doc in more.items():
        write("policy", name + ".json", json.dumps(doc))


def run_record(seconds):
    return {"ok": True, "outcome": "exited with status 0", "seconds": seconds,
            "wall_seconds": seconds + 0.1, "user_seconds": seconds, "system_seconds": 0.01,
            "max_rss_kib": 20480, "reported_seconds": None, "image": "/tmp/i.png",
            "log": "/tmp/log.txt"}


def ratio(value):
    return {"rounds": 3, "normalized_ratio": value,
            "ratio_interval": {"lower": value * 0.98, "upper": value * 1.02},
            "relative_half_width": 0.02, "log_ratio_median": 0.1, "log_ratio_mad_scaled": 0.01,
            "tracer_median_seconds": 1.5, "baseline_median_seconds": 1.0}


def metrics():
    return {"size_mismatch": False, "width": 16, "height": 16, "expected_width": 16,
            "expected_height": 16, "mean_error": 0.001, "rms_error": 0.002, "psnr_db": None,
            "max_error": 0.01, "max_pixel": [1, 2, 0], "max_actual_value": 0.5,
            "max_expected_value": 0.5, "pixels_over_warn": 0, "pixels_over_fail": 0,
            "percent_over_fail": 0.0, "mean_luminance_actual": 0.3,
            "mean_luminance_expected": 0.3, "nonfinite_values": 0, "nonfinite_pixels": 0,
            "first_nonfinite_pixel": [0, 0], "expected_nonfinite_pixels": 0}


def revision(role):
    return {"role": role, "repository": "/tmp/repo",
            "worktree": {"path": "/tmp/wt", "revision": "main", "ref_name": "refs/heads/main",
                         "sha": "a" * 40, "short_sha": "aaaaaaa", "subject": "s",
                         "author": "A", "commit_time": "2026-01-01T00:00:00Z", "dirty": False},
            "adapter": {"name": "make-nff", "hash": "b" * 64, "file": "make-nff.json"},
            "build": {"record_version": 1, "sha": "a" * 40, "dirty": False,
                      "adapter_name": "make-nff", "adapter_hash": "b" * 64, "compiler": "gcc",
                      "key": "k", "build_dir": "/tmp/b", "src_dir": "/tmp/s",
                      "steps": [{"argv": ["make"], "outcome": "exited with status 0",
                                 "succeeded": True, "wall_seconds": 1.0, "cpu_seconds": 1.0,
                                 "log": "/tmp/l"}],
                      "total_seconds": 1.0, "cached": False, "success": True, "failure": "",
                      "log_tail": ""}}


def scene(sid, roles, change):
    runs = {"baseline": run_record(1.0)}
    for role in roles:
        runs[role] = run_record(1.5)
    s = {"scene": {"id": sid, "scene": sid, "size": 1, "width": 16, "height": 16},
         "scene_sha256": "c" * 64, "status": "measured", "stop_reason": "stop_converged",
         "seconds_spent": 3.0, "failure": None, "warmup": {},
         "rounds": [{"order": ["baseline"] + roles, "runs": runs}],
         "ratios": {role: ratio(1.5) for role in roles}, "change": None,
         "images": [{"role": role, "reference": "golden", "actual": "/tmp/a.png",
                     "expected": "/tmp/e.png", "verdict": "pass", "metrics": metrics(),
                     "evidence": []} for role in roles]}
    if change:
        s["change"] = {"rounds": 3, "change": 0.01,
                       "change_interval": {"lower": -0.01, "upper": 0.03}, "confidence": 0.95,
                       "interval_kind": "confidence-sequence",
                       "log_change_median": 0.01, "log_change_mad_scaled": 0.01,
                       "base": ratio(1.5), "head": ratio(1.52),
                       "mann_whitney": {"u": 3.0, "z": 0.1, "p_value": 0.5},
                       "equivalence_interval": {"lower": -0.02, "upper": 0.04},
                       "equivalence_confidence": 0.99,
                       "one_look_interval": {"lower": 0.0, "upper": 0.02},
                       "one_look_confidence": 0.9, "verdict": "UNCHANGED"}
    return s


def document(kind):
    roles = ["tracer"] if kind == "run" else ["base", "head"]
    return {"schema_version": 1, "kind": kind, "raygate_version": "0.1.0",
            "started_at": "2026-01-01T00:00:00Z", "finished_at": "2026-01-01T00:01:00Z",
            "complete": True, "machine": {"hostname": "h"},
            "baseline": {"version": "raygate-baseline 0.1.0", "source_sha256": "d" * 64,
                         "accel": "none", "sampling": "center", "timing": "process-wall"},
            "suite": "ci", "shard": "", "settings": {"schedule": "alternate"},
            "revisions": [revision(r) for r in roles],
            "scenes": [scene("balls", roles, kind == "compare"),
                       scene("gears", roles, kind == "compare")],
            "scores": {r: {"scenes": 2, "score": 1.5, "interval": {"lower": 1.4, "upper": 1.6}}
                       for r in roles}}


def results_seeds():
    for kind in ("run", "compare"):
        write("results", kind + ".json", json.dumps(document(kind), indent=1))  # one readable pair
    breakers = {
        "kind": lambda d: d.update(kind="weird"),
        "status": lambda d: d["scenes"][0].update(status="exploded"),
        "twice": lambda d: d["scenes"].append(copy.deepcopy(d["scenes"][0])),
        "negative": lambda d: d["scenes"][0]["ratios"]["base"].update(normalized_ratio=-1),
        "verdict": lambda d: d["scenes"][1]["change"].update(verdict="FASTER"),
        "failure": lambda d: d["scenes"][0].update(
            status="failed", stop_reason="failed",
            failure={"role": "head", "run": run_record(0.5)}),
        "cachegrind": lambda d: d["scenes"][0]["rounds"][0]["runs"]["head"].update(
            cachegrind={k: 18446744073709551615 for k in
                        ["Ir", "I1mr", "ILmr", "Dr", "D1mr", "DLmr", "Dw", "D1mw", "DLmw"]}),
        "schema": lambda d: d.update(schema_version=99),
        "shard": lambda d: d["settings"].update(shard={"index": 1, "count": 2}),
        "p-value": lambda d: d["scenes"][0]["change"]["mann_whitney"].update(p_value=2),
        "interval": lambda d: d["scenes"][0]["ratios"]["head"].update(
            ratio_interval={"lower": 2, "upper": 1}),
        "role": lambda d: d["revisions"][0].update(role="mallory"),
        "old-change": lambda d: [d["scenes"][0]["change"].pop(k) for k in
                                 ["interval_kind", "equivalence_interval",
                                  "equivalence_confidence", "one_look_interval",
                                  "one_look_confidence", "confidence"]],
        "partial": lambda d: d["scenes"][0].update(partial_round={"base": run_record(1.0)}),
        "warmup": lambda d: d["scenes"][0].update(warmup={"base": [run_record(1.0)]}),
        "nonfinite": lambda d: d["scenes"][0]["images"][0]["metrics"].update(
            psnr_db=None, mean_error=None),
        "scaling": lambda d: d.update(scaling={"families": []}),
        "empty-scenes": lambda d: d.update(scenes=[], scores={}),
        "incomplete": lambda d: d.update(complete=False, finished_at=""),
    }
    for name, breaker in breakers.items():
        doc = document("compare")
        breaker(doc)
        write("results", name + ".json", json.dumps(doc, separators=(",", ":")))
    write("results", "big.json", '{"schema_version": 1, "kind": 1e400}')


def project_config_seeds():
    texts = {
        "all": 'repo = ".."\nadapter = "make-nff"\nsuite = "ci"\npolicy = "gate.json"\n'
               'store = "results.db"\n',
        "url": 'repo = "https://example.com/t.git"\nstore = "postgresql://u@h/db"\n',
        "ini": "[raygate]\nrepo = x\n",
        "comment": "# defaults\nsuite = 'full' # trailing\n",
        "list": 'suite = ["ci", "full"]\n',
        "unknown": 'colour = "blue"\n',
        "empty-value": 'repo = ""\n',
        "multiline": 'adapter = """make\nnff"""\n',
        "dotted": 'a.b = 1\n',
        "equals": "repo==x\n",
        "unicode": 'repo = "d\u00e9p\u00f4t"\n',
        "empty": "",
        "policy-missing": 'policy = "missing.json"\n',
        "absolute": 'store = "/tmp/results.db"\nrepo = "/tmp/repo"\n',
        "dotdot": 'adapter = "../../x.json"\nsuite = "../"\n',
        "git-url": 'repo = "git@github.com:a/b.git"\n',
        "crlf": 'repo = "x"\r\nsuite = "ci"\r\n',
        "bare": "repo\n",
        "number": "repo = 5\n",
        "bool": "store = true\n",
        "inline-table": 'repo = {a = 1}\n',
        "escapes": 'repo = "a\\tb\\u0000c"\n',
        "duplicate": 'repo = "a"\nrepo = "b"\n',
        "section-dotted": "[a.b]\nrepo = 1\n",
    }
    for name, text in texts.items():
        write("project_config", name + ".toml", text)


if __name__ == "__main__":
    nff_seeds()
    adapter_seeds()
    suite_seeds()
    policy_seeds()
    results_seeds()
    project_config_seeds()
