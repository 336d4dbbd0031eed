#!/usr/bin/env python3
"""liquid_capture as a user runs it, for the checks a single command cannot make: interrupting a
run, resuming it, folders shared by two runs, frame ranges and names, the files' contents. Only the
standard library (and OpenVDB's Python module for the volume check). Used by ctest:
    capture_checks.py CHECK --tool liquid_capture --scene tiny.json --work DIR [--docs caches.md]
Each check raises (exit 1, naming what is wrong) or prints 'ok'."""
import argparse
import json
import math
import os
import re
import select
import shutil
import signal
import struct
import subprocess
import sys
import time
import zlib

SMALL = ["--width", "48", "--height", "36", "--validation"]


def fail(message):
    raise SystemExit("FAILED: " + message)


def simulated_domain(scene):
    """The box the liquid runs in: the scene's domain snapped to whole cubic cells of its longest
    side over grid_resolution (README, `domain`), which an axis may pass by up to half a cell."""
    h = max(scene["domain"]) / scene["grid_resolution"]
    return [max(1, math.floor(d / h + 0.5)) * h for d in scene["domain"]]  # std::round


def run(args, expect=0):
    result = subprocess.run([ARGS.tool] + args, capture_output=True, text=True, timeout=600)
    if result.returncode != expect:
        fail(f"{' '.join(args)}: exit {result.returncode}, expected {expect}\n{result.stdout}\n{result.stderr}")
    return result


def files(folder):
    return sorted(os.listdir(folder))


def png_complete(path):
    """A whole PNG: the signature, every chunk's CRC, and IEND last."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        return False
    at = 8
    while at + 12 <= len(data):
        (length,) = struct.unpack(">I", data[at:at + 4])
        kind = data[at + 4:at + 8]
        body = data[at + 8:at + 8 + length]
        (crc,) = struct.unpack(">I", data[at + 8 + length:at + 12 + length])
        if zlib.crc32(kind + body) != crc:
            return False
        at += 12 + length
        if kind == b"IEND":
            return at == len(data)
    return False


def stats_rows(folder):
    lines = open(os.path.join(folder, "stats.csv")).read().splitlines()
    header = lines[0].split(",")
    return [dict(zip(header, line.split(","))) for line in lines[1:]]


def read_ply(path):
    """The reader docs/caches.md gives, so the recipe is what is tested."""
    namespace = {}
    exec(DOC_READER, namespace)
    return namespace["read_liquid_ply"](path)


def start_and_interrupt(args, after_frame_line, sig, cwd=None):
    """Starts a run, waits until it reports `after_frame_line` frames done, sends `sig`."""
    process = subprocess.Popen([ARGS.tool] + args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=cwd)
    for line in process.stdout:
        if line.startswith(f"frame {after_frame_line} of "):
            process.send_signal(sig)
            break
    out, err = process.communicate(timeout=600)
    return process.returncode, err


def check_interrupt(sig):
    out = os.path.join(ARGS.work, "interrupted")
    shutil.rmtree(out, ignore_errors=True)
    code, err = start_and_interrupt([ARGS.scene, "-e", "400", "-o", out] + SMALL, 3, sig)
    if code != 130:
        fail(f"exit {code} after {signal.Signals(sig).name}, expected 130: {err}")
    name = signal.Signals(sig).name
    if err.strip().count("\n") != 0 or f"interrupted ({name})" not in err:
        fail(f"stderr should be one line naming {name}: {err!r}")
    names = files(out)
    if any(n.endswith(".partial") for n in names):
        fail(f"partial files left: {names}")
    frames = [n for n in names if n.endswith(".png")]
    rows = stats_rows(out)
    if len(frames) < 3 or len(frames) >= 400:
        fail(f"{len(frames)} frames written; the run should have stopped early, after frame 3")
    if [int(r["frame"]) for r in rows] != list(range(1, len(frames) + 1)):
        fail(f"stats.csv rows {[r['frame'] for r in rows]} do not match the {len(frames)} frames written")
    if not all(png_complete(os.path.join(out, f)) for f in frames):
        fail("a frame is not a complete PNG")
    summary = json.load(open(os.path.join(out, "summary.json")))
    if summary["status"] != "interrupted" or summary["frames_written"] != len(frames):
        fail(f"summary.json: {summary['status']}, {summary['frames_written']} frames")


def check_resume(scene=None, label=""):
    whole, cut = os.path.join(ARGS.work, "whole" + label), os.path.join(ARGS.work, "resumed" + label)
    for folder in (whole, cut):
        shutil.rmtree(folder, ignore_errors=True)
    common = [scene or ARGS.scene, "-s", "0", "-e", "24", "--export-particles"] + SMALL
    run(common + ["-o", whole])
    code, err = start_and_interrupt(common + ["-o", cut, "--checkpoint-every", "3"], 5, signal.SIGINT)
    if code != 130:
        fail(f"the run to resume exited {code}, expected 130 (interrupted): {err}")
    kept = len([n for n in files(cut) if n.endswith(".png")])
    if kept >= 25:
        fail("the run to resume was not interrupted before its end")
    resumed = run(["--resume", cut, "--validation"])
    if "resumed after frame" not in resumed.stdout:
        fail("the resumed run does not say where it resumed")
    if files(whole) != [n for n in files(cut) if n != "checkpoint.bin"]:
        fail(f"different files: {files(whole)} vs {files(cut)}")
    for name in files(whole):
        if name.endswith((".png", ".ply")) and open(os.path.join(whole, name), "rb").read() != open(
                os.path.join(cut, name), "rb").read():
            fail(f"{name} differs between the uninterrupted and the resumed run")
    timing = lambda row: {k: v for k, v in row.items() if k != "wall_ms" and not k.startswith("gpu_ms.")}
    if [timing(r) for r in stats_rows(whole)] != [timing(r) for r in stats_rows(cut)]:
        fail("stats.csv diagnostics differ between the uninterrupted and the resumed run")
    print(f"resumed after an interrupt with {kept} frames written; 25 frames bit-identical")
    return whole


def check_adaptive():
    """A scene with adaptive_time_step and a largest step 8 times the tiny scene's: every frame
    still falls on its time (frame x frame_seconds), its steps are the CFL's (shorter than the
    largest, so more of them per frame than the plan's), and a resumed run matches bit for bit."""
    scene = json.load(open(ARGS.scene))
    scene["time_step"] *= 8
    scene["adaptive_time_step"] = {}
    path = os.path.join(ARGS.work, "adaptive.json")
    json.dump(scene, open(path, "w"))
    out = check_resume(path, "_adaptive")
    record = json.load(open(os.path.join(out, "capture.json")))
    frame_seconds = record["frames"]["frame_seconds"]
    largest = scene["time_step"]
    rows = stats_rows(out)
    for r in rows:
        t, dt = float(r["time_s"]), float(r["time_step_s"])
        if abs(t - int(r["frame"]) * frame_seconds) > 1e-6 * max(1.0, t):
            fail(f"frame {r['frame']} at t = {t} s, not {int(r['frame']) * frame_seconds} s")
        if int(r["frame"]) > 0 and not 0 < dt < largest:
            fail(f"frame {r['frame']}: time step {dt} s, expected an adaptive one below {largest} s")
    steps = [int(r["step"]) for r in rows]
    per_frame = [b - a for a, b in zip(steps, steps[1:])]
    if min(per_frame) <= record["frames"]["steps_per_frame"]:
        fail(f"steps per frame {per_frame}: the CFL steps should be more than the plan's {record['frames']['steps_per_frame']}")
    print(f"adaptive: {len(rows)} frames on their times, {min(per_frame)} to {max(per_frame)} steps each")


def check_folders():
    # The folder's writability is probed under a name of its own: a user's file is never touched.
    mine = os.path.join(ARGS.work, "users_folder")
    shutil.rmtree(mine, ignore_errors=True)
    os.makedirs(mine)
    for name in (".write_probe", ".liquid_capture_probe"):
        open(os.path.join(mine, name), "w").write("the user's own file\n")
    # (with --video where ffmpeg is installed, whose folder is probed too)
    run([ARGS.scene, "-e", "1", "-o", mine, "--video", os.path.join(mine, "v.mp4")] + SMALL
        if shutil.which("ffmpeg") else [ARGS.scene, "-e", "1", "-o", mine] + SMALL)
    for name in (".write_probe", ".liquid_capture_probe"):
        if open(os.path.join(mine, name)).read() != "the user's own file\n":
            fail(f"the run touched the user's {name}")
    out = os.path.join(ARGS.work, "shared_folder")
    shutil.rmtree(out, ignore_errors=True)
    run([ARGS.scene, "-e", "3", "--export-particles", "-o", out] + SMALL)
    open(os.path.join(out, "notes.txt"), "w").write("the user's own file\n")
    before = files(out)
    second = run([ARGS.scene, "-e", "1", "-o", out] + SMALL, expect=1)
    if second.stderr.count("\n") != 1 or "--overwrite" not in second.stderr:
        fail(f"a second run into the folder should refuse in one line naming --overwrite: {second.stderr!r}")
    if files(out) != before:
        fail("the refused run changed the folder")
    run([ARGS.scene, "-e", "1", "-o", os.path.join(out, "shot_##.png"), "--overwrite"] + SMALL)
    expected = ["capture.json", "notes.txt", "shot_01.png", "stats.csv", "summary.json"]
    if files(out) != expected:
        fail(f"after --overwrite the folder holds {files(out)}, expected {expected}")
    missing = os.path.join(ARGS.work, "never_made", "deeper")
    shutil.rmtree(os.path.dirname(missing), ignore_errors=True)
    run([ARGS.scene, "--width", "70000", "-o", missing], expect=2)
    run([ARGS.scene, "--width", "60000", "-o", missing], expect=1)  # refused by the device's limits
    if os.path.exists(os.path.dirname(missing)):
        fail("a run that failed before its first frame left a new folder behind")


def contents(folder):
    """Every file's bytes by name (no folders)."""
    return {n: open(os.path.join(folder, n), "rb").read() for n in files(folder)
            if os.path.isfile(os.path.join(folder, n))}


def check_failsafe():
    """A failed run never destroys earlier good output: a resume that fails (here: no such device)
    leaves the run's record, table and summary as they were, and can be resumed once the cause is
    gone; an --overwrite run that fails before its first frame
    leaves the old run's files in place, and one that succeeds replaces them."""
    out = os.path.join(ARGS.work, "failsafe")
    shutil.rmtree(out, ignore_errors=True)
    code, err = start_and_interrupt([ARGS.scene, "-s", "0", "-e", "30", "--checkpoint-every", "2", "-o", out] + SMALL,
                                    4, signal.SIGINT)
    if code != 130:
        fail(f"the run to resume exited {code}, expected 130: {err}")
    before = contents(out)
    env = dict(os.environ, RASTERLIQUIDS_DEVICE="nosuchgpu")
    result = subprocess.run([ARGS.tool, "--resume", out], capture_output=True, text=True, timeout=600, env=env)
    if result.returncode == 0 or result.stderr.count("\n") != 1:
        fail(f"a resume on a missing device should fail in one line: exit {result.returncode}, {result.stderr!r}")
    if contents(out) != before:
        fail(f"the failed resume changed the folder: {sorted(before)} -> {files(out)}")
    # A checkpoint damaged on disk (one byte of a particle's position) is refused in one line,
    # and the folder is left as it was.
    checkpoint = os.path.join(out, "checkpoint.bin")
    intact = open(checkpoint, "rb").read()
    damaged = bytearray(intact)
    damaged[len(damaged) // 2] ^= 0x10
    open(checkpoint, "wb").write(damaged)
    before = contents(out)
    refused = run(["--resume", out], expect=1)
    if refused.stderr.count("\n") != 1 or "damaged checkpoint" not in refused.stderr:
        fail(f"a damaged checkpoint should be refused in one line: {refused.stderr!r}")
    if contents(out) != before:
        fail("the refused resume changed the folder")
    open(checkpoint, "wb").write(intact)
    record = os.path.join(out, "capture.json")
    kept = open(record, "rb").read()
    open(record, "wb").write(kept[: len(kept) // 2])
    refused = run(["--resume", out], expect=1)
    if refused.stderr.count("\n") != 1 or "capture.json: not valid JSON" not in refused.stderr:
        fail(f"a damaged capture.json should be refused in one line naming it: {refused.stderr!r}")
    # A record's values are held to their flags' ranges: an edited one is refused naming the field.
    for field, value, message in (("steps_per_frame", 0, "frames.steps_per_frame: must be an integer in [1, 100000], got 0"),
                                  ("end", -3, "frames.end: must be an integer in ["),
                                  ("start", 2 ** 31 - 1, "frames.start: must be an integer in [0, 1000000]")):
        edited = json.loads(kept)
        edited["frames"][field] = value
        open(record, "w").write(json.dumps(edited))
        refused = run(["--resume", out], expect=1)
        if refused.stderr.count("\n") != 1 or message not in refused.stderr:
            fail(f"frames.{field} = {value} in capture.json should be refused in one line naming it: {refused.stderr!r}")
    # A record is sized and its nesting counted before it is read whole or parsed: a deeply nested
    # one (it crashed the resume), an oversized one and a link to an endless file are refused at
    # once, in one line.
    for content, message in ((b"[" * 200000 + b"]" * 200000, "capture.json: not a capture's record (nested deeper than 10 levels)"),
                             (b" " * (17 << 20), "capture.json: not a capture's record (not a regular file of at most 16 MiB)"),
                             (None, "capture.json: not a capture's record (not a regular file of at most 16 MiB)")):
        os.remove(record)
        if content is None:
            os.symlink("/dev/zero", record)
        else:
            open(record, "wb").write(content)
        begin = time.monotonic()
        refused = run(["--resume", out], expect=1)
        if refused.stderr.count("\n") != 1 or message not in refused.stderr or time.monotonic() - begin > 20:
            fail(f"a bad record should be refused at once in one line saying {message!r}: {refused.stderr!r}")
    os.remove(record)
    edited = json.loads(kept)
    edited["view"]["camera_position"] = [1]
    open(record, "w").write(json.dumps(edited))
    refused = run(["--resume", out], expect=1)
    if "view.camera_position: must be empty or 3 numbers" not in refused.stderr:
        fail(f"a camera position of one number should be refused: {refused.stderr!r}")
    open(record, "wb").write(kept)
    run(["--resume", out, "--validation"])
    if not {"capture.json", "stats.csv", "summary.json"} <= set(files(out)):
        fail(f"the resumed run's record is missing: {files(out)}")

    old = contents(out)
    unstable = os.path.join(os.path.dirname(ARGS.scene), "unstable_2d.json")
    failed = run([unstable, "-e", "2", "--steps-per-frame", "20", "-o", out, "--overwrite"] + SMALL, expect=1)
    if "unstable" not in failed.stderr:
        fail(f"the overwriting run should fail as unstable: {failed.stderr!r}")
    if contents(out) != old:
        fail(f"an --overwrite run that failed before its first frame changed the old run's files: {files(out)}")
    run([ARGS.scene, "-e", "2", "-o", out, "--overwrite"] + SMALL)
    if files(out) != ["capture.json", "frame_00001.png", "frame_00002.png", "stats.csv", "summary.json"]:
        fail(f"after a successful --overwrite the folder holds {files(out)}")
    print(f"a failed resume and a failed --overwrite left {len(old)} files as they were")


def check_replace():
    """--overwrite keeps the replaced run set aside until the new run ends well: a run that fails
    after writing a frame removes its files and puts the old run back; after a run killed outright
    the next run into the folder puts the old run back and says so; a run the user stops (SIGINT)
    is the run, and the old one is deleted."""
    out = os.path.join(ARGS.work, "replace")
    shutil.rmtree(out, ignore_errors=True)
    run([ARGS.scene, "-e", "2", "--export-particles", "-o", out] + SMALL)
    old = contents(out)
    unstable = os.path.join(os.path.dirname(ARGS.scene), "unstable_2d.json")
    # Frame 0, the initial state, is written; the steps to frame 1 blow up.
    failed = run([unstable, "-s", "0", "-e", "2", "--steps-per-frame", "20", "-o", out, "--overwrite"] + SMALL, expect=1)
    if "unstable" not in failed.stderr or "frame 1 of 3" not in failed.stdout:
        fail(f"the overwriting run should fail as unstable after writing frame 0: {failed.stdout!r} {failed.stderr!r}")
    if files(out) != sorted(old) or contents(out) != old:
        fail(f"a failed --overwrite run should leave the old run as it was: {files(out)}")
    code, err = start_and_interrupt([ARGS.scene, "-e", "400", "-o", out, "--overwrite"] + SMALL, 2, signal.SIGKILL)
    if not any(n.startswith(".replaced-run-") for n in files(out)):
        fail(f"the killed --overwrite run left no set-aside run: {files(out)}")
    refused = run([ARGS.scene, "-e", "1", "-o", out] + SMALL, expect=1)
    if "put back the run that a killed --overwrite run had set aside" not in refused.stdout or \
            refused.stderr.count("\n") != 1 or "holds another capture's files" not in refused.stderr:
        fail(f"the next run should put the old run back, then refuse the folder: {refused.stdout!r} {refused.stderr!r}")
    if files(out) != sorted(old) or contents(out) != old:
        fail(f"after a killed --overwrite run the next run should have put the old run back: {files(out)}")
    code, err = start_and_interrupt([ARGS.scene, "-e", "400", "-o", out, "--overwrite"] + SMALL, 2, signal.SIGINT)
    names = files(out)
    if code != 130 or any(n.startswith(".replaced-run-") or n.endswith(".ply") for n in names) or \
            json.load(open(os.path.join(out, "summary.json")))["status"] != "interrupted":
        fail(f"an --overwrite run stopped by the user should keep its frames and delete the old run: exit {code}, {names}")
    print(f"a failed and a killed --overwrite run left {len(old)} files as they were; a stopped one replaced them")


def check_leftovers():
    """A set-aside folder that a killed run left is read by the state its name says: one ending in
    .incomplete (killed while the replaced run's files were moving in or out) has its files moved
    back and nothing deleted; a .discarded-run- one (killed while deleting the replaced run, after
    ending well) is deleted and the finished run kept; only a whole .replaced-run- one has the
    killed run's files removed and the replaced run put back."""
    out = os.path.join(ARGS.work, "leftovers")
    shutil.rmtree(out, ignore_errors=True)
    run([ARGS.scene, "-e", "2", "--export-particles", "-o", out] + SMALL)
    old = contents(out)

    def next_run(expected, says, state):
        refused = run([ARGS.scene, "-e", "1", "-o", out] + SMALL, expect=1)
        if says not in refused.stdout or refused.stderr.count("\n") != 1 or \
                "holds another capture's files" not in refused.stderr:
            fail(f"{state}: the next run should say {says!r}, then refuse the folder: "
                 f"{refused.stdout!r} {refused.stderr!r}")
        if files(out) != sorted(expected) or contents(out) != expected:
            fail(f"{state}: the next run left {files(out)}, expected {sorted(expected)}")

    # Killed while setting the old run aside: part of it moved, nothing of the new run written.
    aside = os.path.join(out, ".replaced-run-99999.incomplete")
    os.mkdir(aside)
    for name in ("capture.json", "frame_00001.png", "particles_00002.ply"):
        os.rename(os.path.join(out, name), os.path.join(aside, name))
    next_run(old, "put back the files of a run that a killed --overwrite run was moving", "a half-filled set-aside")
    # Killed while putting the old run back: the new run's files gone, part of the old one back.
    aside = os.path.join(out, ".replaced-run-99999.incomplete")
    os.mkdir(aside)
    for name in ("frame_00002.png", "stats.csv", "summary.json"):
        os.rename(os.path.join(out, name), os.path.join(aside, name))
    next_run(old, "put back the files of a run that a killed --overwrite run was moving", "a half-emptied set-aside")
    # Killed after ending well, while the replaced run was deleted: the finished run stays.
    run([ARGS.scene, "-e", "3", "-o", out, "--overwrite"] + SMALL)
    new = contents(out)
    discarded = os.path.join(out, ".discarded-run-99999")
    os.mkdir(discarded)
    for name in ("frame_00001.png", "stats.csv", "summary.json"):
        open(os.path.join(discarded, name), "wb").write(old[name])
    next_run(new, "deleted .discarded-run-99999/, a replaced run whose deletion was cut short",
             "a half-deleted replaced run")
    # Killed after setting the old run aside whole and writing its own files: they go, the old run comes back.
    aside = os.path.join(out, ".replaced-run-99999")
    os.mkdir(aside)
    for name, data in old.items():
        open(os.path.join(aside, name), "wb").write(data)
    next_run(old, "put back the run that a killed --overwrite run had set aside", "a whole set-aside")
    print("a half-filled, a half-emptied, a half-deleted and a whole set-aside folder were each recovered")


def check_refusals():
    """Bad path flags are refused by name before the run, in one line with exit status 2, nothing
    written: an empty --video or --resume, a --video that is the output folder, a --set path that
    names no field."""
    out = os.path.join(ARGS.work, "refused.mp4")
    for args, message in (([ARGS.scene, "-e", "1", "-o", out, "--video", ""] + SMALL, "--video: needs a file name"),
                          (["--resume", ""], "--resume: needs a capture folder"),
                          ([ARGS.scene, "-o", out, "--video", out], f"--video {out}: is the output folder"),
                          ([ARGS.scene, "-o", out, "--set", "a..b=1"], "--set a..b: not a field path")):
        shutil.rmtree(out, ignore_errors=True)
        refused = run(args, expect=2)
        if refused.stderr.count("\n") != 1 or message not in refused.stderr or refused.stdout:
            fail(f"{args}: should be refused in one line saying {message!r}: {refused.stdout!r} {refused.stderr!r}")
        if os.path.exists(out) or os.path.exists(out + ".partial"):
            fail(f"{args}: the refused run wrote {out}")


def check_lock_write():
    """A write that fails while the folder's lock is written (a full disk; here a file size limit of
    0 bytes, so no file gets a byte) fails in one line and leaves no new folder behind."""
    import resource
    top = os.path.join(ARGS.work, "never_locked")
    shutil.rmtree(top, ignore_errors=True)

    def no_file_bytes():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write past the limit fails instead of killing
        resource.setrlimit(resource.RLIMIT_FSIZE, (0, 0))
    result = subprocess.run([ARGS.tool, ARGS.scene, "-e", "1", "-o", os.path.join(top, "deeper")] + SMALL,
                            capture_output=True, text=True, timeout=600, preexec_fn=no_file_bytes)
    if result.returncode != 1 or result.stderr.count("\n") != 1 or "cannot write the folder's lock" not in result.stderr:
        fail(f"a failed lock write should fail in one line: exit {result.returncode}, {result.stderr!r}")
    if os.path.exists(top):
        fail(f"a run whose lock could not be written left {top} behind: {os.listdir(top)}")


# A closed cube, 6 cm across, faces wound outward.
CUBE_OBJ = """v -0.03 -0.03 -0.03\nv 0.03 -0.03 -0.03\nv 0.03 0.03 -0.03\nv -0.03 0.03 -0.03
v -0.03 -0.03 0.03\nv 0.03 -0.03 0.03\nv 0.03 0.03 0.03\nv -0.03 0.03 0.03
f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6
"""


def check_resume_elsewhere():
    """A run started with relative paths, of a scene whose mesh obstacle's file is relative to the
    scene's folder, resumes from another working folder: capture.json records the scene absolute."""
    base = os.path.join(ARGS.work, "mesh_scene")
    shutil.rmtree(base, ignore_errors=True)
    os.makedirs(os.path.join(base, "meshes"))
    open(os.path.join(base, "meshes", "cube.obj"), "w").write(CUBE_OBJ)
    scene = json.load(open(ARGS.scene))
    scene["obstacles"] = [{"shape": "mesh", "file": "meshes/cube.obj", "center": [0.2, 0.05, 0.1]}]
    json.dump(scene, open(os.path.join(base, "scene.json"), "w"))
    code, err = start_and_interrupt(["scene.json", "-e", "6", "--checkpoint-every", "1", "-o", "out"] + SMALL, 2,
                                    signal.SIGINT, cwd=base)
    if code not in (0, 130):
        fail(f"the run to resume exited {code}: {err}")
    recorded = json.load(open(os.path.join(base, "out", "capture.json")))["scene_source"]
    if recorded != os.path.join(base, "scene.json"):
        fail(f"capture.json records the scene as {recorded!r}, not the absolute {os.path.join(base, 'scene.json')!r}")
    resumed = subprocess.run([ARGS.tool, "--resume", os.path.join(base, "out"), "--validation"], capture_output=True,
                             text=True, timeout=600, cwd=ARGS.work)
    if resumed.returncode != 0:
        fail(f"the resume from another folder failed: exit {resumed.returncode}, {resumed.stderr!r}")
    frames = [n for n in files(os.path.join(base, "out")) if n.endswith(".png")]
    if len(frames) != 6:
        fail(f"the resumed run wrote {frames}, expected frames 1 to 6")


def check_lock():
    """A folder is one run's while it runs: a --resume or an --overwrite run into it is refused in
    one line naming the running one's process id, and the running one finishes unharmed."""
    out = os.path.join(ARGS.work, "locked")
    shutil.rmtree(out, ignore_errors=True)
    process = subprocess.Popen([ARGS.tool, ARGS.scene, "-e", "400", "--checkpoint-every", "1", "-o", out] + SMALL,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    for line in process.stdout:
        if line.startswith("frame 3 of "):
            break
    for args in (["--resume", out], [ARGS.scene, "-e", "2", "-o", out, "--overwrite"] + SMALL):
        refused = run(args, expect=1)
        if refused.stderr.count("\n") != 1 or f"in use by another liquid_capture (pid {process.pid})" not in refused.stderr:
            process.kill()
            fail(f"{' '.join(args[:2])} into a running capture's folder should be refused naming pid {process.pid}: "
                 f"{refused.stderr!r}")
    process.send_signal(signal.SIGINT)
    out_text, err = process.communicate(timeout=600)
    if process.returncode != 130:
        fail(f"the running capture exited {process.returncode} after the refused runs, expected 130: {err}")
    if any(n.startswith(".liquid_capture.lock") for n in os.listdir(out)):
        fail("the lock was left behind")
    run(["--resume", out])  # the folder is free again
    print(f"a resume and an --overwrite run were refused while pid {process.pid} ran")


def check_fps():
    """--fps F gives exactly F frames per simulated second: frame f at t = f / F (the step shortened
    to fit), and F recorded as given in capture.json and the PLY headers."""
    out = os.path.join(ARGS.work, "fps")
    shutil.rmtree(out, ignore_errors=True)
    run([ARGS.scene, "-e", "3", "--fps", "24", "--export-particles", "-o", out] + SMALL)
    frames = json.load(open(os.path.join(out, "capture.json")))["frames"]
    if frames["fps"] != 24 or not frames["fps_exact"] or abs(frames["time_step_s"] * frames["steps_per_frame"] * 24 - 1) > 1e-12:
        fail(f"capture.json frames {frames}: expected exactly 24 frames/s")
    for r in stats_rows(out):
        t, expected = float(r["time_s"]), int(r["frame"]) / 24
        if abs(t - expected) > 1e-6 * max(1.0, expected):  # the solver's clock, to its float steps
            fail(f"frame {r['frame']} at t = {t} s, not {expected} s")
    header = open(os.path.join(out, "particles_00002.ply"), "rb").read().split(b"end_header")[0]
    if b"comment fps 24\n" not in header:
        fail(f"the PLY header does not give the rate: {header!r}")
    probe = run([ARGS.scene, "--fps", "30", "--dry-run"] + SMALL)
    if "(30 frames/s)" not in probe.stdout:
        fail(f"the dry run does not say 30 frames/s: {probe.stdout}")
    print(f"--fps 24: {frames['steps_per_frame']} steps of {frames['time_step_s']} s a frame")


def check_dry_run():
    out = os.path.join(ARGS.work, "dry_run")
    shutil.rmtree(out, ignore_errors=True)
    result = run(["small_3d", "--dry-run", "--set", "stiffness=21", "--set", "fluid_blocks[0].max=[0.1,0.1,0.1]",
                  "--steps-per-frame", "1", "-o", os.path.join(out, "shot_###.png")] + SMALL)
    for expected in ("assets/scenes/small_3d.json, with --set", '"stiffness": 21', "frames: 1 to 60 written (60)",
                     "shot_001.png .. shot_060.png", "estimate: about "):
        if expected not in result.stdout:
            fail(f"the dry run does not say {expected!r}:\n{result.stdout}")
    if os.path.exists(out):
        fail("the dry run created the output folder")


def check_estimate():
    """The dry run's estimate of a range that starts late against the run itself: the startup, a
    warm-up of each kind of frame and medians, so neither the first use of a pipeline nor one slow
    frame sets it (it was 40 % high when the first simulated frame was timed cold)."""
    out = os.path.join(ARGS.work, "estimate")
    shutil.rmtree(out, ignore_errors=True)
    plan = ["small_3d", "-s", "20", "-e", "22", "--width", "96", "--height", "72", "--validation", "-o", out]
    probe = run(plan + ["--dry-run"])
    line = next((l for l in probe.stdout.splitlines() if l.startswith("estimate: about ")), None)
    if line is None or " = " not in line or "startup " not in line:
        fail(f"no estimate in seconds with its startup:\n{probe.stdout}")
    estimate = float(line.split(" = ")[1].split(" s ")[0])
    begin = time.monotonic()
    run(plan)
    real = time.monotonic() - begin
    print(f"estimated {estimate:.1f} s, ran {real:.1f} s")
    if not 0.75 <= estimate / real <= 1.33:
        fail(f"the dry run estimated {estimate:.1f} s for a run of {real:.1f} s")


def check_names():
    """Output names a file system cannot hold are refused before the run, in one line, with no
    folder left behind: a frame name (at the run's last frame) whose temporary .partial passes 255
    bytes, a run of 250 '#'."""
    out = os.path.join(ARGS.work, "names")
    shutil.rmtree(out, ignore_errors=True)
    cases = (("-o", os.path.join(out, "f_" + "#" * 250 + ".png")),
             ("-o", os.path.join(out, "x" * 240 + "_####.png")),
             ("--particles-name", "p" * 240 + "_####.ply"),
             ("--video", os.path.join(ARGS.work, "v" * 250 + ".mp4")))
    for flag, value in cases:
        args = [ARGS.scene, "-e", "2"] + ([] if flag == "-o" else ["-o", out]) + [flag, value] + SMALL
        refused = run(args, expect=2)
        if refused.stderr.count("\n") != 1 or "255" not in refused.stderr and "longer than" not in refused.stderr:
            fail(f"{flag} of {len(os.path.basename(value))} bytes should be refused in one line: {refused.stderr!r}")
        if os.path.exists(out):
            fail(f"a refused {flag} left {out} behind")
    # User text echoed in a message is escaped onto one line, and a huge one is cut.
    for args, echoed in (([ARGS.scene, "--no\nsuch"], "--no\\nsuch"),
                         ([ARGS.scene, "--" + "k" * 100000], " bytes)")):
        refused = run(args, expect=2)
        if refused.stderr.count("\n") != 1 or echoed not in refused.stderr or len(refused.stderr) > 5000:
            fail(f"a bad flag should be echoed on one line, escaped and cut: {refused.stderr[:300]!r}")
    # 247 bytes and .partial: 255, which fits.
    run([ARGS.scene, "-e", "2", "-o", os.path.join(out, "x" * 238 + "_####.png")] + SMALL)
    if files(out)[-1] != "x" * 238 + "_0002.png":
        fail(f"a name of 247 bytes should be written: {files(out)}")


def check_range():
    out = os.path.join(ARGS.work, "range")
    shutil.rmtree(out, ignore_errors=True)
    run([ARGS.scene, "-s", "3", "-e", "5", "-o", os.path.join(out, "liquid_####.png"), "--particles-name",
         "points_##.ply", "--steps-per-frame", "2"] + SMALL)
    expected = ["capture.json", "liquid_0003.png", "liquid_0004.png", "liquid_0005.png", "points_03.ply",
                "points_04.ply", "points_05.ply", "stats.csv", "summary.json"]
    if files(out) != expected:
        fail(f"files {files(out)}, expected {expected}")
    record = json.load(open(os.path.join(out, "capture.json")))
    dt = record["frames"]["time_step_s"]
    for row in stats_rows(out):
        f = int(row["frame"])
        if int(row["step"]) != 2 * f or abs(float(row["time_s"]) - 2 * f * dt) > 1e-6:
            fail(f"frame {f} is at step {row['step']}, t = {row['time_s']}; expected step {2 * f}, t = {2 * f * dt}")
        ply = read_ply(os.path.join(out, f"points_{f:02d}.ply"))
        if ply["frame"] != f or abs(ply["time_s"] - float(row["time_s"])) > 1e-6:
            fail(f"points_{f:02d}.ply says frame {ply['frame']} at {ply['time_s']} s")
        if ply["id"] != list(range(len(ply["id"]))) or len(ply["id"]) != int(row["active_particles"]):
            fail("particle ids are not 0 .. N-1 in order")
        if not 0.5 < max(ply["density"]) <= float(row["max_density_ratio"]) + 1e-3:
            fail(f"per-particle density up to {max(ply['density'])}, grid max {row['max_density_ratio']}")
    summary = json.load(open(os.path.join(out, "summary.json")))
    if (summary["frames_written"], summary["first_frame"], summary["last_frame"], summary["status"]) != (
            3, 3, 5, "finished") or not summary["gpu_ms_median_per_frame"]:
        fail(f"summary.json: {summary}")
    # An emitter added with --set gives new particles the next ids; an id follows one particle.
    jet = os.path.join(ARGS.work, "range_jet")
    shutil.rmtree(jet, ignore_errors=True)
    emitter = '[{"position": [0.25, 0.12, 0.1], "velocity": [-0.6, 0, 0], "radius": 0.02, "capacity": 300}]'
    run([ARGS.scene, "-e", "4", "--export-particles", "--set", "emitters=" + emitter, "-o", jet] + SMALL)
    frames = [read_ply(os.path.join(jet, f"particles_{f:05d}.ply")) for f in range(1, 5)]
    counts = [len(p["id"]) for p in frames]
    if not counts[0] < counts[-1] <= 1280 + 300 or any(p["id"] != list(range(len(p["id"]))) for p in frames):
        fail(f"particle counts {counts}: the emitter should add particles with the next ids")
    step = 1.5 * max(float(r["max_speed_m_s"]) for r in stats_rows(jet)) * 3 * dt + 1e-6
    for before, after in zip(frames, frames[1:]):
        moved = max(abs(after[c][i] - before[c][i]) for c in ("x", "y", "z") for i in range(len(before["id"])))
        if moved > step:
            fail(f"a particle's id jumped {moved} m in one frame, more than the fastest particle moves ({step} m)")
    # Frame 0 is the initial state: the lattice at rest, at t = 0.
    zero = os.path.join(ARGS.work, "range_zero")
    shutil.rmtree(zero, ignore_errors=True)
    run([ARGS.scene, "-s", "0", "-e", "0", "--export-particles", "-o", zero] + SMALL)
    ply = read_ply(os.path.join(zero, "particles_00000.ply"))
    if ply["time_s"] != 0.0 or any(v != 0.0 for v in ply["vx"] + ply["vy"] + ply["vz"]):
        fail("frame 0 is not the initial state at rest")
    # Deep inside the block the lattice is at the rest density (read at the particles, which sit where
    # the separable splat's deposit peaks, up to 1 % above the cells' mean); its edges read less.
    if not 0.95 < max(ply["density"]) <= 1.01 or not min(ply["density"]) < 0.5:
        fail(f"frame 0's particle densities span {min(ply['density'])} to {max(ply['density'])}, expected up to 1")


def check_volume():
    import pyopenvdb as vdb
    out = os.path.join(ARGS.work, "volume")
    shutil.rmtree(out, ignore_errors=True)
    run([ARGS.scene, "-s", "0", "-e", "2", "--export-volume", "-o", out] + SMALL)
    record = json.load(open(os.path.join(out, "capture.json")))
    domain, cells = record["scene"]["domain"], record["scene"]["grid_resolution"]
    h = max(domain) / cells
    for row in stats_rows(out):
        f = int(row["frame"])
        grids, meta = vdb.readAll(os.path.join(out, f"volume_{f:05d}.vdb"))
        by_name = {g.name: g for g in grids}
        if sorted(by_name) != ["density", "velocity"]:
            fail(f"grids {sorted(by_name)}")
        if abs(meta["time_s"] - float(row["time_s"])) > 1e-6 or meta["frame"] != f:
            fail(f"frame {f}: metadata {meta}")
        density = by_name["density"]
        if abs(density.transform.voxelSize()[0] - h) > 1e-6:
            fail(f"voxel size {density.transform.voxelSize()}, cell size {h}")
        if any(abs(c - h / 2) > 1e-6 for c in density.transform.indexToWorld((0, 0, 0))):
            fail("voxel (0, 0, 0) is not at the first cell's centre")
        values = [v.value for v in density.iterOnValues()]
        if abs(max(values) - float(row["max_density_ratio"])) > 1e-3:
            fail(f"frame {f}: largest density {max(values)}, stats.csv {row['max_density_ratio']}")
        speeds = [sum(c * c for c in v.value) ** 0.5 for v in by_name["velocity"].iterOnValues()]
        if f > 0 and not 0.0 < max(speeds) < 10.0 * float(row["max_speed_m_s"]) + 1.0:
            fail(f"frame {f}: grid speeds up to {max(speeds)}")


def check_surface():
    """--export-surface: the level set read back by OpenVDB, the mesh by the reader docs/caches.md
    gives (closed, wound outward, inside the domain), the export's time in stats and summary."""
    import pyopenvdb as vdb
    namespace = {}
    exec(doc_block(ARGS.docs, "def read_liquid_mesh"), namespace)
    read_mesh = namespace["read_liquid_mesh"]
    out = os.path.join(ARGS.work, "surface")
    shutil.rmtree(out, ignore_errors=True)
    last = run([ARGS.scene, "-e", "2", "--export-surface", "-o", out] + SMALL).stdout.splitlines()[-1]
    if not re.search(r"; the surface export took [0-9.]+ ms a frame$", last):
        fail(f"last line {last!r} does not give the surface export's time")
    record = json.load(open(os.path.join(out, "capture.json")))
    domain, cells = record["scene"]["domain"], record["scene"]["grid_resolution"]
    voxel = max(domain) / cells / 2
    summary = json.load(open(os.path.join(out, "summary.json")))
    if not 0.0 < summary["surface_export_ms"]["median"] <= summary["surface_export_ms"]["max"]:
        fail(f"summary surface_export_ms {summary.get('surface_export_ms')}")
    for row in stats_rows(out):
        f = int(row["frame"])
        if not float(row["surface_ms"]) > 0.0:
            fail(f"frame {f}: surface_ms {row['surface_ms']}")
        grids, meta = vdb.readAll(os.path.join(out, f"surface_{f:05d}.vdb"))
        if [g.name for g in grids] != ["surface"] or grids[0].gridClass != "level set":
            fail(f"frame {f}: grids {[(g.name, g.gridClass) for g in grids]}")
        surface = grids[0]
        if abs(surface.transform.voxelSize()[0] - voxel) > 1e-6 or abs(surface.background - 3 * voxel) > 1e-6:
            fail(f"frame {f}: voxel {surface.transform.voxelSize()}, background {surface.background}, expected {voxel}")
        if any(abs(c - voxel / 2) > 1e-6 for c in surface.transform.indexToWorld((0, 0, 0))):
            fail(f"frame {f}: voxel (0, 0, 0) is not half a voxel from the domain's corner")
        if abs(meta["time_s"] - float(row["time_s"])) > 1e-6 or meta["frame"] != f:
            fail(f"frame {f}: metadata {meta}")
        mesh = read_mesh(os.path.join(out, f"mesh_{f:05d}.ply"))
        edges = {}
        for t in mesh["triangles"]:
            for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
                edges[(a, b)] = edges.get((a, b), 0) + 1
        if any(n != 1 or edges.get((b, a)) != 1 for (a, b), n in edges.items()):
            fail(f"frame {f}: the mesh is not closed and consistently wound")
        v = mesh["vertices"]
        volume = sum(v[a][0] * (v[b][1] * v[c][2] - v[b][2] * v[c][1]) - v[a][1] * (v[b][0] * v[c][2] - v[b][2] * v[c][0])
                     + v[a][2] * (v[b][0] * v[c][1] - v[b][1] * v[c][0]) for a, b, c in mesh["triangles"]) / 6
        lo, hi = record["scene"]["fluid_blocks"][0]["min"], record["scene"]["fluid_blocks"][0]["max"]
        # Two frames in, the block has barely moved. Its surface holds less: this scene's point splat
        # leaves the density below rho0 near the walls and the kernel rounds the block's free edges
        # (the volume against the mass is the GPU test's, on a pool).
        block = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])
        if not 0.7 * block < volume < 1.05 * block:
            fail(f"frame {f}: the mesh encloses {volume} m^3, the block {block} m^3")
        box = simulated_domain(record["scene"])
        if any(not -1e-6 <= p[i] <= box[i] + 1e-6 for p in v for i in range(3)):
            fail(f"frame {f}: a vertex outside the domain {box}")
        if len(mesh["velocities"]) != len(v) or max(sum(c * c for c in u) for u in mesh["velocities"]) > 100.0:
            fail(f"frame {f}: velocities")


def check_whitewater():
    """--export-whitewater and --export-volume on the tiny scene with "whitewater": {}: every frame's
    PLY read by the reader docs/caches.md gives (frame 0's empty one too), its count against
    stats.csv, its types 1 to 3 named in the header, one id a particle; the VDB's foam grid summing
    to the file's foam particles; the export's time in stats, summary and the last line; and a
    resumed run writing them on under the recorded name."""
    import pyopenvdb as vdb
    namespace = {}
    exec(doc_block(ARGS.docs, "def read_liquid_whitewater"), namespace)
    read_whitewater = namespace["read_liquid_whitewater"]
    scene = json.load(open(ARGS.scene))
    scene["whitewater"] = {}
    path = os.path.join(ARGS.work, "whitewater.json")
    json.dump(scene, open(path, "w"))
    out = os.path.join(ARGS.work, "whitewater")
    shutil.rmtree(out, ignore_errors=True)
    # The block is let go at rest: its first spray comes about frame 10, once it has fallen.
    last = run([path, "-s", "0", "-e", "14", "--export-whitewater", "--export-volume", "-o", out]
               + SMALL).stdout.splitlines()[-1]
    if not re.search(r"; the whitewater export took [0-9.]+ ms a frame$", last):
        fail(f"last line {last!r} does not give the whitewater export's time")
    summary = json.load(open(os.path.join(out, "summary.json")))
    if not 0.0 < summary["whitewater_export_ms"]["median"] <= summary["whitewater_export_ms"]["max"]:
        fail(f"summary whitewater_export_ms {summary.get('whitewater_export_ms')}")
    domain = simulated_domain(scene)
    counts = []
    for row in stats_rows(out):
        f = int(row["frame"])
        ply = read_whitewater(os.path.join(out, f"whitewater_{f:05d}.ply"))
        n = len(ply["type"])
        counts.append(n)
        if ply["frame"] != f or abs(ply["time_s"] - float(row["time_s"])) > 1e-6:
            fail(f"frame {f}: the header says frame {ply['frame']} at {ply['time_s']} s")
        if ply["types"] != {1: "spray", 2: "foam", 3: "bubble"}:
            fail(f"frame {f}: the header names the types {ply['types']}")
        if n != int(row["whitewater_particles"]) or not float(row["whitewater_ms"]) > 0.0:
            fail(f"frame {f}: {n} particles in the file, stats.csv {row['whitewater_particles']} "
                 f"in {row['whitewater_ms']} ms")
        if any(t not in (1, 2, 3) for t in ply["type"]) or len(set(ply["id"])) != n:
            fail(f"frame {f}: types {sorted(set(ply['type']))}, {len(set(ply['id']))} ids for {n} particles")
        if any(not -1e-6 <= p[i] <= domain[i] + 1e-6 for p in zip(ply["x"], ply["y"], ply["z"]) for i in range(3)):
            fail(f"frame {f}: a particle outside the domain")
        if any(not 0.0 <= a <= float(row["time_s"]) + 1e-6 for a in ply["age"]):
            fail(f"frame {f}: ages {min(ply['age'])} to {max(ply['age'])} s")
        grids, _ = vdb.readAll(os.path.join(out, f"volume_{f:05d}.vdb"))
        by_name = {g.name: g for g in grids}
        if sorted(by_name) != ["density", "foam", "velocity"]:
            fail(f"frame {f}: grids {sorted(by_name)}")
        foam = by_name["foam"]
        h = foam.transform.voxelSize()[0]
        if abs(h - by_name["density"].transform.voxelSize()[0]) > 1e-9 or foam.transform.indexToWorld(
                (0, 0, 0)) != by_name["density"].transform.indexToWorld((0, 0, 0)):
            fail(f"frame {f}: the foam grid is not placed as the density's")
        total = sum(v.value for v in foam.iterOnValues()) * h ** 3
        if abs(total - ply["type"].count(2)) > 1e-3 * max(1, ply["type"].count(2)):
            fail(f"frame {f}: the foam grid sums to {total} particles, the file holds {ply['type'].count(2)}")
    if counts[0] != 0 or max(counts) == 0:
        fail(f"particles per frame {counts}: none at frame 0, some later expected")

    resumed = os.path.join(ARGS.work, "whitewater_resumed")
    shutil.rmtree(resumed, ignore_errors=True)
    code, err = start_and_interrupt([path, "-s", "0", "-e", "24", "--whitewater-name", "w_####.ply", "-o", resumed,
                                     "--checkpoint-every", "3"] + SMALL, 5, signal.SIGINT)
    if code != 130:
        fail(f"the run to resume exited {code}, expected 130 (interrupted): {err}")
    run(["--resume", resumed, "--validation"])
    if json.load(open(os.path.join(resumed, "capture.json")))["names"]["whitewater"] != "w_####.ply":
        fail("capture.json does not record the whitewater files' name")
    rows = stats_rows(resumed)
    if [int(r["frame"]) for r in rows] != list(range(25)):
        fail(f"the resumed run's stats.csv has frames {[r['frame'] for r in rows]}")
    # The checkpoint carries the secondary particles: every frame as an uninterrupted run writes it.
    straight = os.path.join(ARGS.work, "whitewater_straight")
    shutil.rmtree(straight, ignore_errors=True)
    run([path, "-s", "0", "-e", "24", "--whitewater-name", "w_####.ply", "-o", straight] + SMALL)
    for row in rows:
        f = int(row["frame"])
        ply = read_whitewater(os.path.join(resumed, f"w_{f:04d}.ply"))
        if len(ply["type"]) != int(row["whitewater_particles"]):
            fail(f"resumed run, frame {f}: the file's count is not stats.csv's")
        expected = read_whitewater(os.path.join(straight, f"w_{f:04d}.ply"))
        if any(ply[k] != expected[k] for k in ("x", "y", "z", "type", "id")):
            fail(f"resumed run, frame {f}: its whitewater differs from the uninterrupted run's")
    print(f"whitewater: {counts} particles in frames 0 to 14, the foam grids summing to the files' foam; resumed "
          "as the uninterrupted run")


def check_video():
    out, video = os.path.join(ARGS.work, "video"), os.path.join(ARGS.work, "liquid.mp4")
    shutil.rmtree(out, ignore_errors=True)
    if os.path.exists(video):
        os.remove(video)
    run([ARGS.scene, "-e", "6", "--width", "47", "--height", "35", "-o", out, "--video", video, "--validation"])
    probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-show_entries", "stream=nb_read_frames,width",
                            "-of", "csv=p=0", video], capture_output=True, text=True)
    if probe.stdout.strip() != "48,6":
        fail(f"ffprobe says {probe.stdout.strip()!r}: expected 6 frames 48 pixels wide (padded to even)")
    # A run that fails after writing a frame leaves the video already there as it was.
    encoded = open(video, "rb").read()
    unstable = os.path.join(os.path.dirname(ARGS.scene), "unstable_2d.json")
    run([unstable, "-s", "0", "-e", "2", "--steps-per-frame", "20", "-o", out, "--video", video, "--overwrite"] + SMALL,
        expect=1)
    if open(video, "rb").read() != encoded or os.path.exists(video + ".partial"):
        fail("a failed --overwrite run replaced the video already there")
    # A run that fails only on validation messages (the layer's best-practice warnings, turned on
    # through the environment) fails like any other: the replaced frames and the video stay.
    before = contents(out)
    env = dict(os.environ, VK_LAYER_ENABLES="VK_VALIDATION_FEATURE_ENABLE_BEST_PRACTICES_EXT")
    result = subprocess.run([ARGS.tool, ARGS.scene, "-e", "3", "-o", out, "--video", video, "--overwrite"] + SMALL,
                            capture_output=True, text=True, timeout=600, env=env)
    if result.returncode == 0:
        print("the validation layer ignores VK_LAYER_ENABLES: no run with validation messages checked")
    elif "validation message" not in result.stderr:
        fail(f"the run with best-practice warnings should fail on them: exit {result.returncode}, {result.stderr!r}")
    elif open(video, "rb").read() != encoded or os.path.exists(video + ".partial") or contents(out) != before:
        fail(f"a run failed by validation messages replaced the video or the frames: {files(out)}")
    # A relative name that ffmpeg would read as an option ("-lead.mp4"), given from another
    # directory: encoded where it was asked for, and recorded absolute for a resume from elsewhere.
    lead, out2 = os.path.join(ARGS.work, "-lead.mp4"), os.path.join(ARGS.work, "video_lead")
    shutil.rmtree(out2, ignore_errors=True)
    if os.path.exists(lead):
        os.remove(lead)
    result = subprocess.run([ARGS.tool, ARGS.scene, "-e", "2", "--width", "48", "--height", "36", "-o", out2,
                             "--video=-lead.mp4", "--validation"], capture_output=True, text=True, timeout=600, cwd=ARGS.work)
    if result.returncode != 0 or not os.path.isfile(lead):
        fail(f"--video=-lead.mp4: exit {result.returncode}, file made: {os.path.isfile(lead)}: {result.stderr}")
    # A video name that is a folder is refused before the run.
    folder_video = os.path.join(ARGS.work, "a_folder.mp4")
    os.makedirs(folder_video, exist_ok=True)
    refused = run([ARGS.scene, "-e", "2", "-o", os.path.join(ARGS.work, "video_folder"), "--video", folder_video] + SMALL,
                  expect=1)
    if "is a folder, not a video file" not in refused.stderr:
        fail(f"a --video that is a folder should be refused before the run: {refused.stderr!r}")
    # An ffmpeg that dies: the frames written so far each have their row, and summary.json says so.
    fake = os.path.join(ARGS.work, "fake_ffmpeg")
    os.makedirs(fake, exist_ok=True)
    with open(os.path.join(fake, "ffmpeg"), "w") as f:
        f.write("#!/bin/sh\nexit 1\n")
    os.chmod(os.path.join(fake, "ffmpeg"), 0o755)
    broken = os.path.join(ARGS.work, "video_broken")
    shutil.rmtree(broken, ignore_errors=True)
    env = dict(os.environ, PATH=fake + os.pathsep + os.environ.get("PATH", ""))
    result = subprocess.run([ARGS.tool, ARGS.scene, "-e", "4", "-o", broken, "--video", os.path.join(ARGS.work, "broken.mp4"),
                             "--overwrite"] + SMALL,
                            capture_output=True, text=True, timeout=600, env=env)
    if result.returncode == 0 or "--video" not in result.stderr:
        fail(f"a run whose ffmpeg died should fail naming --video: exit {result.returncode}, {result.stderr!r}")
    pngs = [n for n in files(broken) if n.endswith(".png")]
    if len(stats_rows(broken)) != len(pngs):
        fail(f"{len(pngs)} frames but {len(stats_rows(broken))} rows in stats.csv after the video failed")
    summary = json.load(open(os.path.join(broken, "summary.json")))
    if "video" not in json.dumps(summary):
        fail(f"summary.json does not say the video failed: {summary}")
    # Replacing a run, a failed video fails the run: its files go and the replaced run comes back.
    before = contents(broken)
    result = subprocess.run([ARGS.tool, ARGS.scene, "-e", "3", "-o", broken, "--video",
                             os.path.join(ARGS.work, "broken.mp4"), "--overwrite"] + SMALL,
                            capture_output=True, text=True, timeout=600, env=env)
    if result.returncode == 0 or "--video" not in result.stderr or contents(broken) != before:
        fail(f"an --overwrite run whose ffmpeg died should put the replaced run back: exit {result.returncode}, "
             f"{files(broken)}, {result.stderr!r}")
    recorded = json.load(open(os.path.join(out2, "capture.json")))["video"]
    if recorded != os.path.abspath(lead):
        fail(f"capture.json records the video as {recorded!r}, not the absolute {os.path.abspath(lead)!r}")


def check_setup_stages():
    """On a terminal the set-up's long stages (reading meshes, carving, compiling pipelines) say what
    is running, so a long wait never looks like a hang; piped, the output has no such line."""
    import pty
    out = os.path.join(ARGS.work, "stages")
    shutil.rmtree(out, ignore_errors=True)
    leader, follower = pty.openpty()
    process = subprocess.Popen([ARGS.tool, ARGS.scene, "--frames", "1", "-o", out] + SMALL,
                               stdout=follower, stderr=follower, stdin=subprocess.DEVNULL)
    os.close(follower)
    seen = b""
    deadline = time.monotonic() + 300
    while True:
        left = deadline - time.monotonic()
        if left <= 0 or not select.select([leader], [], [], left)[0]:
            process.kill()
            process.wait()
            os.close(leader)
            fail(f"the run on a terminal did not end within 300 s: {seen.decode(errors='replace')!r}")
        try:
            chunk = os.read(leader, 4096)
        except OSError:  # the terminal closes when the run ends
            break
        if not chunk:
            break
        seen += chunk
    os.close(leader)
    if process.wait(timeout=600) != 0:
        fail(f"the run on a terminal failed: {seen.decode(errors='replace')}")
    text = seen.decode(errors="replace")
    for stage in ["reading the scene and its meshes...", "setting up the simulation"]:
        if stage not in text:
            fail(f"on a terminal, no '{stage}' line in: {text!r}")
    shutil.rmtree(out)
    piped = run([ARGS.scene, "--frames", "1", "-o", out] + SMALL)
    if "setting up" in piped.stdout or "reading the scene" in piped.stdout:
        fail(f"piped output shows the set-up stages: {piped.stdout!r}")


def doc_block(path, definition):
    """The first python block of docs/caches.md that holds `definition`."""
    text = open(path).read()
    for block in text.split("```python")[1:]:
        code = block.split("```")[0]
        if definition in code:
            return code
    fail(f"{path}: no python block holds {definition}")


def doc_reader(path):
    """The python block of docs/caches.md that defines read_liquid_ply."""
    return doc_block(path, "def read_liquid_ply")


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("check")
    parser.add_argument("--tool", required=True)
    parser.add_argument("--scene", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--docs", required=True)
    ARGS = parser.parse_args()
    DOC_READER = doc_reader(ARGS.docs)
    os.makedirs(ARGS.work, exist_ok=True)
    checks = {"sigint": lambda: check_interrupt(signal.SIGINT), "sigterm": lambda: check_interrupt(signal.SIGTERM),
              "resume": check_resume, "dryrun": check_dry_run, "estimate": check_estimate, "names": check_names, "folders": check_folders, "range": check_range, "volume": check_volume, "surface": check_surface,
              "whitewater": check_whitewater,
              "video": check_video, "adaptive": check_adaptive,
              "failsafe": check_failsafe, "lock": check_lock, "fps": check_fps, "replace": check_replace,
              "leftovers": check_leftovers,
              "refusals": check_refusals, "lock_write": check_lock_write, "resume_elsewhere": check_resume_elsewhere,
              "setup_stages": check_setup_stages}
    checks[ARGS.check]()
    print("ok")
