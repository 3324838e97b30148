"""The Markdown summary of bench/sim-validation: reads the documents it left in a folder.

Usage: sim_validation_summary.py DIR COMPARES TRACER...
"""
import json
import os
import sys


def load(path):
    return json.load(open(path)) if os.path.exists(path) else None


def wall(path):
    """(seconds, exit code, load average) of the command that wrote `path`."""
    try:
        seconds, status, load_average = open(path + ".wall").read().split()
        return float(seconds), int(status), load_average
    except (OSError, ValueError):
        return None


def ratios(doc):
    rows = {}
    for scene in doc["scenes"] if doc else []:
        r = scene.get("ratios", {}).get("tracer")
        if scene["status"] == "measured" and r:
            rows[scene["scene"]["id"]] = (r["normalized_ratio"], r["rounds"])
    return rows


def r_squared(xs, ys):
    n = len(xs)
    if n < 3:
        return float("nan")
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    syy = sum((y - my) ** 2 for y in ys)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    return sxy * sxy / (sxx * syy) if sxx > 0 and syy > 0 else float("nan")


def determinism(doc):
    """Scenes whose simulated runs all had identical costs, of scenes measured."""
    same = total = 0
    for scene in doc["scenes"] if doc else []:
        costs = {}
        for rnd in scene["rounds"]:
            for role, run in rnd["runs"].items():
                costs.setdefault(role, set()).add(run["seconds"])
        if costs:
            total += 1
            same += all(len(v) == 1 for v in costs.values())
    return same, total


def main():
    out, compares, tracers = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    print("## 1. Simulated-cost ratio against CPU-time ratio, per scene\n")
    for tracer in tracers:
        sim = load(f"{out}/run-{tracer}-sim.json")
        cpu = load(f"{out}/run-{tracer}-cpu.json")
        if not sim or not cpu:
            print(f"{tracer}: not measured\n")
            continue
        s, c = ratios(sim), ratios(cpu)
        ids = [i for i in s if i in c]
        print(f"### {tracer} (suite {sim['suite']})\n")
        print("| scene | sim ratio | cpu ratio (rounds) | sim / cpu |")
        print("|---|---|---|---|")
        for i in ids:
            print(f"| {i} | {s[i][0]:.4f} | {c[i][0]:.4f} ({c[i][1]}) | {s[i][0] / c[i][0]:.3f} |")
        xs, ys = [s[i][0] for i in ids], [c[i][0] for i in ids]
        same, total = determinism(sim)
        print(f"\nr² = {r_squared(xs, ys):.3f} over {len(ids)} scenes; counts repeated exactly "
              f"in {same} of {total} scenes; wall time sim run {wall(out + f'/run-{tracer}-sim.json')}, "
              f"cpu run {wall(out + f'/run-{tracer}-cpu.json')} (seconds, exit, load)\n")

    print("## 2. Two sim runs\n")
    print("| tracer | scenes | largest relative difference of a ratio | wall s (first, second) |")
    print("|---|---|---|---|")
    for tracer in tracers:
        a = ratios(load(f"{out}/run-{tracer}-sim.json"))
        b = ratios(load(f"{out}/run-{tracer}-sim-again.json"))
        ids = [i for i in a if i in b]
        if not ids:
            continue
        worst = max(abs(b[i][0] / a[i][0] - 1) for i in ids)
        first = wall(f"{out}/run-{tracer}-sim.json")
        second = wall(f"{out}/run-{tracer}-sim-again.json")
        print(f"| {tracer} | {len(ids)} | {worst:.3g} | {first and first[0]}, {second and second[0]} |")

    print("\n## 3. The gate at a 0.5% limit (fixture tracer, +1% = every 100th pixel again)\n")
    for kind, label in (("aa", "A/A"), ("slow", "+1%")):
        exits, changes, walls = [], [], []
        for i in range(1, compares + 1):
            path = f"{out}/compare-{kind}-{i}.json"
            doc, w = load(path), wall(path)
            if not doc or not w:
                continue
            exits.append(w[1])
            walls.append(w[0])
            changes += [f"{s['scene']['id']} {100 * s['change']['change']:+.4f}%"
                        f"{' exact' if s['change'].get('exact') else ''} {s['change'].get('verdict', '?')}"
                        for s in doc["scenes"] if s.get("change")]
        if not exits:
            continue
        costs = {}
        for i in range(1, compares + 1):
            doc = load(f"{out}/compare-{kind}-{i}.json")
            for scene in doc["scenes"] if doc else []:
                for rnd in scene["rounds"]:
                    for role in ("base", "head"):
                        costs.setdefault((scene["scene"]["id"], role), set()).add(
                            rnd["runs"][role]["seconds"])
        distinct = max((len(v) for v in costs.values()), default=0)
        print(f"- {label}: every base and head run of every compare, per scene: at most {distinct} "
              f"distinct cost(s) over {2 * len(exits)} runs each")
        print(f"- {label}: {len(exits)} compares, exit 1 in {sum(e == 1 for e in exits)}, "
              f"exit codes {sorted(set(exits))}; wall s min {min(walls):.0f} max {max(walls):.0f}; "
              f"changes seen: {sorted(set(changes))}")


    print("\n## 4. What a simulated run costs: CPU seconds of the tracer's runs\n")
    print("| tracer | scenes | one sim round, CPU s (valgrind) | one timed round, CPU s | slowdown |")
    print("|---|---|---|---|---|")
    for tracer in tracers:
        sim = load(f"{out}/run-{tracer}-sim.json")
        cpu = load(f"{out}/run-{tracer}-cpu.json")
        if not sim or not cpu:
            continue
        def per_round(doc):
            total = {}
            for scene in doc["scenes"]:
                runs = [r["runs"]["tracer"] for r in scene["rounds"]]
                if runs:
                    total[scene["scene"]["id"]] = sum(
                        r["user_seconds"] + r["system_seconds"] for r in runs) / len(runs)
            return total
        a, b = per_round(sim), per_round(cpu)
        ids = [i for i in a if i in b]
        sa, sb = sum(a[i] for i in ids), sum(b[i] for i in ids)
        print(f"| {tracer} | {len(ids)} | {sa:.1f} | {sb:.2f} | {sa / sb:.0f}x |")


main()
