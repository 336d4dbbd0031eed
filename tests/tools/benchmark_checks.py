#!/usr/bin/env python3
"""Checks of liquid_benchmark's reference, its comparisons and its viewer group that one command
line cannot make.

  benchmark_checks.py CHECK --tool PATH --results FIXTURE --work DIR [--viewer PATH]

CHECK: roundtrip | reference | alternating | live | splat | viewer | viewer_skipped.
roundtrip, reference and alternating work on saved JSON (FIXTURE, a real run's output, and copies
of it with one pass made slower): no device. live, splat and viewer run the GPU, with --validation.
No check asserts anything about real speed.
"""
import argparse
import copy
import json
import os
import re
import shutil
import subprocess
import sys


def check(condition, message):
    print(("ok: " if condition else "FAIL: ") + message, flush=True)
    if not condition:
        sys.exit(1)


def run(args, *flags, expect=0, env=None):
    command = [args.tool, *flags]
    print("$", " ".join(command), flush=True)
    result = subprocess.run(command, capture_output=True, text=True, timeout=900, env=env)
    print(result.stdout, result.stderr, sep="", flush=True)
    check(result.returncode == expect, f"exit code {result.returncode}, expected {expect}")
    return result


def load(path):
    with open(path) as f:
        return json.load(f)


def save(document, name, args):
    path = os.path.join(args.work, name)
    with open(path, "w") as f:
        json.dump(document, f, indent=2)
    return path


def medians(results):
    """{configuration: {measure: ms}} of a benchmark JSON, as the tool reads it."""
    out = {}
    for r in results["results"]:
        m = {"frame": r["frame_wall_ms"]["median"]}
        m.update({p: s["median"] for p, s in r["gpu_ms_per_frame"].items()})
        out[r["name"]] = m
    return out


def reference_medians(reference):
    return {c["name"]: {"frame": c["frame_ms"], **c["gpu_ms"]} for c in reference["configurations"]}


def scaled(results, factor, configuration=None, passes=()):
    """A copy of a benchmark JSON with every time times `factor`, and `passes` of `configuration`
    (full names, or "frame") times 2 on top."""
    out = copy.deepcopy(results)
    for r in out["results"]:
        for s in [r["frame_wall_ms"], *r["gpu_ms_per_frame"].values()]:
            for k in ("median", "min", "max"):
                s[k] *= factor
        if r["name"] == configuration:
            for p in passes:
                s = r["frame_wall_ms"] if p == "frame" else r["gpu_ms_per_frame"][p]
                for k in ("median", "min", "max"):
                    s[k] *= 2
    return out


def warnings(output):
    return [line for line in output.splitlines() if line.startswith("WARNING")]


def roundtrip(args):
    # A reference saved from a run's JSON holds its medians, device and settings, and a reference
    # saved again from that reference is the same.
    results = load(args.results)
    first, second = os.path.join(args.work, "ref1.json"), os.path.join(args.work, "ref2.json")
    for path in (first, second):
        if os.path.exists(path):
            os.remove(path)
    run(args, "--from", args.results, "--save-reference", first)
    r1 = load(first)
    check(r1["kind"] == "reference" and r1["format"] == 1, "the file is a liquid_benchmark reference, format 1")
    check(r1["device"] == {"name": results["device"]["name"], "driver": results["device"]["driver"]},
          f"it records the device and driver: {r1['device']}")
    check(r1["settings"]["steps_per_frame"] == results["settings"]["steps_per_frame"]
          and r1["settings"]["frame_width"] == results["settings"]["frame_width"]
          and r1["settings"]["validation"] == results["settings"]["validation"], "it records the settings")
    check(reference_medians(r1) == medians(results), "it holds the run's frame and pass medians, per configuration")
    check([c["name"] for c in r1["configurations"]] == [r["name"] for r in results["results"]],
          "in the run's order")
    run(args, "--from", first, "--save-reference", second)
    r2 = load(second)
    check(reference_medians(r2) == reference_medians(r1) and r2["device"] == r1["device"]
          and r2["settings"] == r1["settings"], "saved again from the reference, it is the same")


def reference(args):
    # Against its own reference a run gives ratios of 1 and no warning; with one pass twice as
    # slow, that pass is warned about, and only it; a uniformly slower run (the machine's drift)
    # gets a note, not a warning.
    results = load(args.results)
    ref = os.path.join(args.work, "reference.json")
    run(args, "--from", args.results, "--save-reference", ref)
    same = run(args, "--from", args.results, "--reference", ref)
    check(not warnings(same.stdout), "an equal run: no WARNING")
    check(re.search(r"^paper_2d_16k/sim splat +[0-9.]+ +[0-9.]+ +1\.00 +1\.00$", same.stdout, re.M) is not None,
          "an equal run: ratio 1.00 on the splat")
    slow = save(scaled(results, 1.0, "paper_2d_16k/sim", ["liquid.splat"]), "splat_2x.json", args)
    out = run(args, "--from", slow, "--reference", ref)
    w = warnings(out.stdout)
    check(len(w) == 1 and w[0].startswith("WARNING: paper_2d_16k/sim splat: 2.00x the reference"),
          f"the splat made 2x slower is warned about, alone: {w}")
    drift = save(scaled(results, 1.6), "drift.json", args)
    out = run(args, "--from", drift, "--reference", ref)
    check(not warnings(out.stdout), "a run 1.6x slower throughout: no WARNING")
    check("note: the whole run is 1.60x the reference" in out.stdout, "but a note that the whole run is slower")
    other = copy.deepcopy(results)
    other["device"]["name"] = "NVIDIA Quadro 2000M"
    other_path = save(other, "other_device.json", args)
    out = run(args, "--from", other_path, "--reference", ref, expect=1)
    check(out.stderr.count("\n") == 1 and "differ in device" in out.stderr and out.stdout == "",
          "a run on another device is refused in one line")


def alternating(args):
    # Saved rounds of two builds: equal builds with round-to-round jitter give no warning; a pass
    # twice as slow in every round gets one; twice as slow in two rounds of three gets none (the
    # rule asks every round); a pass 1.3x slower while the builds move 40% between rounds gets none.
    results = load(args.results)
    jitter = [1.00, 1.04, 0.97]
    old = [save(scaled(results, j), f"old_{k}.json", args) for k, j in enumerate(jitter)]

    def new(name, factors, slow_rounds=()):
        return [save(scaled(results, f, "paper_2d_16k/sim+render" if k in slow_rounds else None, ["liquid.splat"]),
                     f"{name}_{k}.json", args) for k, f in enumerate(factors)]

    equal = run(args, "--old-results", ",".join(old), "--new-results", ",".join(new("equal", [1.02, 0.99, 1.01])))
    check(not warnings(equal.stdout), "equal builds: no WARNING")
    check("no measure slower beyond the round-to-round noise" in equal.stdout, "equal builds: says so")
    check(re.search(r"^paper_2d_16k/sim\+render fxaa .* same$", equal.stdout, re.M) is not None,
          "each measure has a line with its verdict")
    slow = run(args, "--old-results", ",".join(old),
               "--new-results", ",".join(new("slow", [1.02, 0.99, 1.01], slow_rounds=(0, 1, 2))))
    w = warnings(slow.stdout)
    check(len(w) == 1 and w[0].startswith("WARNING: paper_2d_16k/sim+render splat: slower, new/old 2.0"),
          f"the splat made 2x slower in every round is warned about, alone: {w}")
    partly = run(args, "--old-results", ",".join(old),
                 "--new-results", ",".join(new("partly", [1.02, 0.99, 1.01], slow_rounds=(0, 2))))
    check(not warnings(partly.stdout), "2x slower in two rounds of three: no WARNING")
    noisy_old = [save(scaled(results, j), f"noisy_old_{k}.json", args) for k, j in enumerate([1.0, 1.4, 1.0])]
    noisy_new = [save(scaled(results, j * 1.3), f"noisy_new_{k}.json", args) for k, j in enumerate([1.0, 1.4, 1.0])]
    noisy = run(args, "--old-results", ",".join(noisy_old), "--new-results", ",".join(noisy_new))
    check(not warnings(noisy.stdout), "1.3x slower while each build moves 40% from round to round: no WARNING")
    clear_old = [save(scaled(results, 1.0), f"clear_old_{k}.json", args) for k in range(3)]
    clear_new = [save(scaled(results, 1.3), f"clear_new_{k}.json", args) for k in range(3)]
    clear = run(args, "--old-results", ",".join(clear_old), "--new-results", ",".join(clear_new))
    check(len(warnings(clear.stdout)) == 10, "1.3x slower everywhere on a steady machine: every measure warned about")
    out = run(args, "--old-results", ",".join(old), "--new-results", ",".join(old[:2]), expect=1)
    check(out.stderr.count("\n") == 1 and "as many rounds" in out.stderr, "unequal round counts: one line")


def live(args):
    # The whole path on the device: a run saves a reference, the next run compares with it, and
    # the alternating comparison runs two builds (here this one twice) round by round.
    json_path, ref = os.path.join(args.work, "live", "benchmark.json"), os.path.join(args.work, "live_ref.json")
    shutil.rmtree(os.path.join(args.work, "live"), ignore_errors=True)
    common = ["--only", "paper_2d_16k/sim", "--quick", "--validation"]
    run(args, *common, "-o", json_path, "--save-reference", ref)
    check(reference_medians(load(ref)) == medians(load(json_path)), "the reference holds the run's medians")
    out = run(args, *common, "-o", json_path, "--reference", ref)
    check("Against the reference" in out.stdout and re.search(r"^paper_2d_16k/sim splat ", out.stdout, re.M),
          "the second run compares with the reference")
    out = run(args, *common, "-o", json_path, "--baseline-binary", args.tool, "--rounds", "2")
    for which in ("old_1", "new_1", "old_2", "new_2"):
        check(os.path.exists(os.path.join(args.work, "live", "rounds", which + ".json")), f"round file {which}.json")
    c = load(os.path.join(args.work, "live", "comparison.json"))
    check(c["rounds"] == 2 and {m["measure"] for m in c["measures"]} >= {"frame", "liquid.splat"},
          "comparison.json holds the frame and the passes over 2 rounds")
    check(re.search(r"^paper_2d_16k/sim splat .*: (same|slower|faster)$", out.stdout, re.M) is not None,
          "the table has a verdict per measure")


def splat(args):
    # Both splat modes side by side: paper_2d_16k/sim is the chapter's point sprites, as before,
    # and paper_2d_16k:separable/sim the separable splat's passes, from the scene key "splat".
    json_path = os.path.join(args.work, "splat", "benchmark.json")
    run(args, "--only", "paper_2d_16k/sim", "--only", "paper_2d_16k:separable/sim", "--quick", "--validation",
        "-o", json_path)
    results = {r["name"]: r for r in load(json_path)["results"]}
    check(sorted(results) == ["paper_2d_16k/sim", "paper_2d_16k:separable/sim"], f"the two rows: {sorted(results)}")
    plain, separable = results["paper_2d_16k/sim"], results["paper_2d_16k:separable/sim"]
    check(plain["splat"] == "point_sprite" and "liquid.splat" in plain["gpu_ms_per_frame"]
          and "liquid.deposit" not in plain["gpu_ms_per_frame"], "the plain name runs the chapter's point sprites")
    check(separable["splat"] == "separable" and "liquid.deposit" in separable["gpu_ms_per_frame"]
          and "liquid.splat" not in separable["gpu_ms_per_frame"], "the :separable row runs the separable splat")


def viewer(args):
    # The viewer's frame rate on both dam breaks at 1024x768, as lines of the table and the JSON.
    json_path = os.path.join(args.work, "viewer", "benchmark.json")
    out = run(args, "--viewer", args.viewer, "--only", "viewer", "--quick", "--validation", "-o", json_path)
    for scene in ("dam_break_2d", "dam_break_3d"):
        check(re.search(rf"^viewer/{scene} +[0-9.]+ +[0-9.]+ +5 +1024x768 ", out.stdout, re.M) is not None,
              f"a table line with the frame rate of {scene} at 1024x768")
    results = {r["name"]: r for r in load(json_path)["results"]}
    for scene in ("dam_break_2d", "dam_break_3d"):
        r = results.get("viewer/" + scene)
        check(r is not None and r["viewer"]["average_fps"] > 0 and r["fps"] > 0 and r["viewer"]["frames"] == 5,
              f"the JSON has viewer/{scene} with its frames per second")


def viewer_skipped(args):
    # No display and no Xvfb: the viewer's rows are skipped with one line each, the run succeeds.
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    env["PATH"] = "/nonexistent"
    json_path = os.path.join(args.work, "viewer_skipped", "benchmark.json")
    out = run(args, "--viewer", args.viewer, "--only", "viewer/dam_break_2d", "--quick", "--validation",
              "-o", json_path, env=env)
    lines = [line for line in out.stdout.splitlines() if "viewer/dam_break_2d" in line and "skipped" in line]
    check(len(lines) == 1 and "no X display" in lines[0] and "Xvfb" in lines[0],
          f"one line says why it is skipped: {lines}")
    skipped = load(json_path)["skipped"]
    check(any(s["name"] == "viewer/dam_break_2d" for s in skipped), "the JSON lists it as skipped")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("check", choices=["roundtrip", "reference", "alternating", "live", "splat", "viewer", "viewer_skipped"])
    p.add_argument("--tool", required=True)
    p.add_argument("--results", required=True)
    p.add_argument("--work", required=True)
    p.add_argument("--viewer")
    args = p.parse_args()
    args.work = os.path.join(args.work, args.check)
    os.makedirs(args.work, exist_ok=True)
    globals()[args.check](args)


if __name__ == "__main__":
    main()
