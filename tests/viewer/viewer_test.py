#!/usr/bin/env python3
"""Runs liquid_viewer under its own Xvfb (with_xvfb.sh) as a person would, with replayed input, and
checks what the node read back at exit (--report) against the same run without the input.

  viewer_test.py MODE --viewer PATH --with-xvfb PATH --scenes DIR --scripts DIR --out DIR [--compare PATH]
                [--viewer-arg ARG ...]
MODE: drag | obstacle | hit3d | shallow_water | camera_reset | resize | golden | bad_reload | no_panel |
paused_reset | screenshots | overlay | panel_size | panel_drag | panel_wrap | whitewater. Every run has --validation: any
validation message makes the viewer exit non-zero and the test fail.
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time
import zlib

SIZE = ["--width", "320", "--height", "240"]


def run(args, name, viewer_args, expect_success=True, cwd=None):
    report = os.path.join(args.out, name + ".json")
    if os.path.exists(report):
        os.remove(report)
    command = [args.with_xvfb, args.viewer, *viewer_args, *args.viewer_arg, "--validation", "--report", report]
    print("$", " ".join(command), flush=True)
    result = subprocess.run(command, capture_output=True, text=True, timeout=300, cwd=cwd)
    print(result.stdout, result.stderr, sep="", flush=True)
    if expect_success and result.returncode != 0:
        sys.exit(f"FAIL: {name}: exit code {result.returncode}")
    with open(report) as f:
        r = json.load(f)
    if r["validation_messages"] != 0:
        sys.exit(f"FAIL: {name}: {r['validation_messages']} validation message(s)")
    forced = [a.split("=", 1)[1] for a in args.viewer_arg if a.startswith("--3d-path=")]
    if forced and r.get("grid_path") != forced[0]:
        sys.exit(f"FAIL: {name}: ran on the 3D path {r.get('grid_path')}, not the forced {forced[0]}")
    return r


def check(condition, message):
    print(("ok: " if condition else "FAIL: ") + message, flush=True)
    if not condition:
        sys.exit(1)


def read_png(path):
    """(width, height, rows of RGBA bytes) of an 8-bit RGBA PNG (what the viewer writes)."""
    with open(path, "rb") as f:
        data = f.read()
    width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
    check(data[24:26] == bytes([8, 6]), f"{path} is 8-bit RGBA")
    chunks, i = b"", 8
    while i < len(data):
        length = int.from_bytes(data[i:i + 4], "big")
        if data[i + 4:i + 8] == b"IDAT":
            chunks += data[i + 8:i + 8 + length]
        i += 12 + length
    raw, stride, rows, previous = zlib.decompress(chunks), 4 * width, [], bytearray(4 * width)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - 4] if x >= 4 else 0
            b, c = previous[x], previous[x - 4] if x >= 4 else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        previous = line
    return width, height, rows


def liquid_pixels(path):
    """Pixels of a 2D view that are not the tank's background (its most common colour)."""
    width, height, rows = read_png(path)
    pixels = [row[i:i + 3] for row in rows for i in range(0, 4 * width, 4)]
    background = max(set(pixels), key=pixels.count)
    return sum(1 for p in pixels if max(abs(a - b) for a, b in zip(p, background)) > 24)


def com(r):
    return r["diagnostics"]["center_of_mass"]


def height_field_camera(domain, rest_depth):
    """The shallow-water view's default camera (liquid::default_height_field_camera): position,
    target, vertical field of view."""
    target = [0.5 * domain[0], 0.5 * rest_depth, 0.5 * domain[1]]
    elevation, distance = math.radians(50), 1.55 * max(domain)
    position = [target[0], target[1] + distance * math.sin(elevation), target[2] + distance * math.cos(elevation)]
    return position, target, 40.0


def height_field_point(pixel, size, camera, level):
    """The domain point (x, y) of the height-field view under a window pixel: where the view ray
    meets the horizontal plane at world height `level` (domain y is world z)."""
    position, target, fov = camera
    forward = [t - p for t, p in zip(target, position)]
    n = math.sqrt(sum(f * f for f in forward))
    forward = [f / n for f in forward]
    right = [-forward[2], 0.0, forward[0]]  # forward x (0, 1, 0)
    n = math.sqrt(sum(r * r for r in right))
    right = [r / n for r in right]
    up = [right[1] * forward[2] - right[2] * forward[1], right[2] * forward[0] - right[0] * forward[2],
          right[0] * forward[1] - right[1] * forward[0]]
    half = math.tan(math.radians(fov) / 2)
    nx, ny = 2 * (pixel[0] + 0.5) / size[0] - 1, 2 * (pixel[1] + 0.5) / size[1] - 1  # Vulkan: y down
    direction = [f + nx * half * size[0] / size[1] * r - ny * half * u for f, r, u in zip(forward, right, up)]
    s = (level - position[1]) / direction[1]
    return position[0] + s * direction[0], position[2] + s * direction[2]


def same_camera(a, b, tolerance=1e-4):
    return all(abs(x - y) < tolerance for key in ("position", "target") for x, y in zip(a[key], b[key]))


def drag(args):
    # A left drag up and to the right through the 2D dam's column (tests/viewer/drag_2d.json).
    scene = os.path.join(args.scenes, "dam_break_2d.json")
    # 2 steps of 0.91 ms a frame: the simulated time the drag was measured over (16 chapter-sized steps).
    common = [scene, "--frames", "30", "--steps-per-frame", "2", *SIZE, "--no-panel"]
    base = run(args, "drag_none", common)
    dragged = run(args, "drag", [*common, "--script", os.path.join(args.scripts, "drag_2d.json")])
    # The brush's last place: the script's last cursor (88, 110) in the 320 x 240 window's 2D
    # layout (liquid::fit_view2d: 308.48 pixels per metre, domain corner at pixel (6, 213)).
    brush = dragged["last_brush"]
    check(abs(brush[0] - (88 - 6) / 308.48) < 2e-3 and abs(brush[1] - (213 - 110) / 308.48) < 2e-3,
          f"the brush followed the cursor: last at {brush[:2]}")
    dx = com(dragged)[0] - com(base)[0]
    dy = com(dragged)[1] - com(base)[1]
    check(dx > 3e-3 and dy > 5e-3, f"the liquid moved the drag's way (up and right): centre of mass moved by ({dx:.4f}, {dy:.4f}) m")
    check(dragged["diagnostics"]["outside_domain"] == 0, "no particle left the domain")


def obstacle(args):
    # A right drag of the sphere of obstacles_2d (at (0.3, 0.22) m) 72 pixels up into the liquid.
    scene = os.path.join(args.scenes, "obstacles_2d.json")
    common = [scene, "--frames", "34", "--steps-per-frame", "8", *SIZE, "--no-panel"]
    base = run(args, "obstacle_none", common)
    moved = run(args, "obstacle", [*common, "--script", os.path.join(args.scripts, "obstacle_2d.json")])
    before, after = base["obstacles"][0], moved["obstacles"][0]
    expected_y = 0.22 + 72 / 308.48
    check(abs(before[1] - 0.22) < 1e-6, f"without the drag the sphere stays at y = {before[1]:.4f}")
    check(abs(after[0] - 0.3) < 2e-3 and abs(after[1] - expected_y) < 5e-3,
          f"the sphere followed the cursor to {after[:2]} (expected (0.3, {expected_y:.4f}))")
    dy = com(moved)[1] - com(base)[1]
    check(dy > 5e-3, f"the liquid was pushed up: centre of mass {dy:.4f} m higher than without the drag")
    inside = moved["diagnostics"]["inside_obstacles"]
    check(inside <= 0.005 * moved["diagnostics"]["active_particles"], f"pushed, not tunnelled: {inside} particles inside obstacles")


def body(args):
    # A right drag on floating_box_2d pulls its dynamic box towards the cursor, held near the top of
    # the window, by a force: it ends two cells (2 cm) or more above where it floats without the drag.
    scene = os.path.join(args.scenes, "floating_box_2d.json")
    common = [scene, "--frames", "120", "--steps-per-frame", "16", *SIZE, "--no-panel"]
    base = run(args, "body_none", common)
    pulled = run(args, "body", [*common, "--script", os.path.join(args.scripts, "body_2d.json")])
    y0 = base["diagnostics"]["bodies"][0]["center"][1]
    y1 = pulled["diagnostics"]["bodies"][0]["center"][1]
    check(y1 > y0 + 0.02, f"the box was pulled up: it ends at y = {y1:.4f} m, {y0:.4f} m without the drag")
    check(pulled["diagnostics"]["outside_domain"] == 0, "no particle left the domain")


def hit3d(args):
    # 3D: a press over the dam's column lands on its surface (the block's front face, z = 0.5 m);
    # a press over empty space lands in the plane through the domain centre facing the camera.
    scene = os.path.join(args.scenes, "dam_break_3d.json")
    script = os.path.join(args.scripts, "hit_3d.json")
    on = run(args, "hit_liquid", [scene, "--frames", "3", *SIZE, "--no-panel", "--script", script])["last_brush"]
    check(abs(on[2] - 0.5) < 0.02 and 0.0 < on[0] < 0.35 and 0.0 < on[1] < 0.42,
          f"over the liquid the brush is on its surface: {on}")
    off = run(args, "hit_empty", [scene, "--frames", "6", *SIZE, "--no-panel", "--script", script])["last_brush"]
    position, target, centre = [0.5, 0.75, 1.5], [0.5, 0.2, 0.25], [0.5, 0.3, 0.25]  # the scene's camera
    forward = [t - p for t, p in zip(target, position)]
    norm = sum(f * f for f in forward) ** 0.5
    distance = sum((o - c) * f / norm for o, c, f in zip(off, centre, forward))
    check(abs(distance) < 0.01 and off[0] > 0.5, f"over empty space it is in the plane through the centre: {off}")


def shallow_water(args):
    # The shallow-water view is a perspective height field: a left drag towards the camera through
    # the near half of the window (tests/viewer/shallow_drag.json, from pixel y 150 to 195 of 240)
    # pushes the liquid of the near half of the plane towards the viewer (domain +y), and a middle
    # drag orbits the camera.
    path = os.path.join(args.scenes, "shallow_water.json")
    scene = json.load(open(path))
    common = [path, "--frames", "24", "--steps-per-frame", "8", *SIZE, "--no-panel"]
    base = run(args, "shallow_none", common)
    dragged = run(args, "shallow_drag", [*common, "--script", os.path.join(args.scripts, "shallow_drag.json")])
    camera = height_field_camera(scene["domain"], scene["rest_depth"])
    check(same_camera(base["camera"], {"position": camera[0], "target": camera[1]}),
          f"without input the camera is the scene's default: {base['camera']}")
    # The brush slides in the horizontal plane at the height it touched the water (about the rest
    # depth, twice it over the raised block): 5 cm of height is under 5 cm on the plane here.
    expected = height_field_point((160, 195), (320, 240), camera, scene["rest_depth"])
    brush = dragged["last_brush"]
    check(abs(brush[0] - expected[0]) < 0.05 and abs(brush[1] - expected[1]) < 0.06,
          f"the brush is where the view ray meets the water: last at {brush[:2]}, expected about {expected}")
    check(brush[1] > 0.5, f"a drag in the near half of the window lands in the near half of the plane: y = {brush[1]:.3f}")
    dy = com(dragged)[1] - com(base)[1]
    check(dy > 2e-4, f"the liquid moved towards the viewer (domain +y): centre of mass moved by {dy:.5f} m")
    check(dragged["diagnostics"]["outside_domain"] == 0, "no particle left the domain")
    orbited = run(args, "shallow_orbit", [path, "--frames", "6", *SIZE, "--no-panel",
                                          "--script", os.path.join(args.scripts, "orbit.json")])
    check(not same_camera(orbited["camera"], base["camera"], 1e-2),
          f"a middle drag orbits the camera: {base['camera']['position']} -> {orbited['camera']['position']}")
    target_moved = max(abs(a - b) for a, b in zip(orbited["camera"]["target"], base["camera"]["target"]))
    check(target_moved < 1e-5, "an orbit keeps the target")


def camera_reset(args):
    # R resets the scene and the camera: after an orbit (tests/viewer/orbit.json) the camera is
    # the scene's again (orbit_reset.json: the same, then R), in 3D and in shallow water.
    for name, frames in (("dam_break_3d", 8), ("shallow_water", 8)):
        path = os.path.join(args.scenes, name + ".json")
        common = [path, "--frames", str(frames), *SIZE, "--no-panel"]
        orbited = run(args, name + "_orbit", [*common, "--script", os.path.join(args.scripts, "orbit.json")])
        reset = run(args, name + "_orbit_reset", [*common, "--script", os.path.join(args.scripts, "orbit_reset.json")])
        scene = json.load(open(path))
        if "camera" in scene:
            default = {"position": scene["camera"]["position"], "target": scene["camera"]["target"]}
        else:
            position, target, _ = height_field_camera(scene["domain"], scene["rest_depth"])
            default = {"position": position, "target": target}
        check(not same_camera(orbited["camera"], default, 1e-2),
              f"{name}: the middle drag orbited the camera to {orbited['camera']['position']}")
        check(same_camera(reset["camera"], default),
              f"{name}: after R the camera is the scene's: {reset['camera']['position']} (default {default['position']})")
        check(reset["steps"] < orbited["steps"], f"{name}: and the scene was reset ({reset['steps']} steps since)")


def resize(args):
    scene = os.path.join(args.scenes, "dam_break_2d.json")
    shot = os.path.join(args.out, "resize.png")
    r = run(args, "resize", [scene, "--frames", "14", "--steps-per-frame", "4", *SIZE, "--screenshot", shot,
                             "--script", os.path.join(args.scripts, "resize.json")])
    check(r["frames"] == 14, f"every frame was drawn: {r['frames']} of 14")
    check(r["swapchain_recreations"] >= 2, f"the swapchain was recreated {r['swapchain_recreations']} times")
    check((r["width"], r["height"]) == (256, 160), f"the last frame is {r['width']} x {r['height']}")
    with open(shot, "rb") as f:
        data = f.read()
    width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
    check((width, height) == (256, 160), f"the screenshot after the resize is {width} x {height}")


def golden(args):
    scene = os.path.join(args.scenes, "dam_break_2d.json")
    shot = os.path.join(args.out, "viewer_dam_break_2d.png")
    # 24 steps (21.8 ms), the time of the 192 chapter-sized steps the golden was first recorded at.
    run(args, "golden", [scene, "--frames", "12", "--steps-per-frame", "2", "--width", "256", "--height", "192",
                         "--no-panel", "--no-overlay", "--screenshot", shot])
    result = subprocess.run([args.compare, shot, "viewer_dam_break_2d"], capture_output=True, text=True)
    print(result.stdout, result.stderr, sep="")
    check(result.returncode == 0, "the last frame matches tests/goldens/viewer_dam_break_2d.png")


def run_with_bad_edit(args, name, size=SIZE):
    """Runs the viewer on a copy of dam_break_2d that is edited badly (stiffness -1) once the
    window is up; returns the report."""
    scene = os.path.join(args.out, name + "_2d.json")
    shutil.copy(os.path.join(args.scenes, "dam_break_2d.json"), scene)
    report = os.path.join(args.out, name + ".json")
    command = [args.with_xvfb, args.viewer, scene, "--frames", "60", *size, "--validation", "--report", report]
    viewer = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    started = viewer.stdout.readline()  # the viewer prints its first line once the window is up
    print(started, end="")
    time.sleep(0.05)
    with open(scene) as f:
        edited = json.load(f)
    edited["stiffness"] = -1
    with open(scene, "w") as f:
        json.dump(edited, f)
    out, err = viewer.communicate(timeout=300)
    print(out, err, sep="")
    check(started.startswith("liquid_viewer: "), "the viewer started")
    check(viewer.returncode == 0, f"the viewer kept running to its last frame (exit {viewer.returncode})")
    with open(report) as f:
        r = json.load(f)
    check(r["validation_messages"] == 0, "no validation message")
    return r


def bad_reload(args):
    # A scene edited on disk while the viewer runs: a bad edit is reported, the old scene keeps running.
    r = run_with_bad_edit(args, "bad_reload")
    check("stiffness" in r["scene_error"], f"the bad edit's error is shown: {r['scene_error']!r}")
    check(r["diagnostics"]["active_particles"] > 0 and r["steps"] > 0, "the old scene kept running")


def no_panel(args):
    # The simulation does not depend on what the window shows: an adaptive scene reaches the same
    # step and time with the panel open or hidden, and an exploding one is caught and paused
    # with the panel hidden too.
    scene = json.load(open(os.path.join(args.scenes, "dam_break_2d.json")))
    scene["adaptive_time_step"] = {}
    adaptive = os.path.join(args.out, "adaptive_2d.json")
    with open(adaptive, "w") as f:
        json.dump(scene, f)
    common = [adaptive, "--frames", "70", "--steps-per-frame", "2", *SIZE]
    shown, hidden = run(args, "adaptive_panel", common), run(args, "adaptive_no_panel", [*common, "--no-panel"])
    check(shown["steps"] == hidden["steps"] and shown["time"] == hidden["time"],
          f"the same steps and time with and without the panel: {shown['time']} s after {shown['steps']} steps, "
          f"{hidden['time']} s after {hidden['steps']} steps")
    check(shown["time"] < 70 * 2 * scene["time_step"], "the steps adapted (shorter than the scene's)")
    unstable = os.path.join(args.scripts, "..", "tools", "unstable_2d.json")
    exploded = run(args, "unstable_no_panel", [unstable, "--frames", "40", "--steps-per-frame", "2", *SIZE, "--no-panel"])
    check(exploded["paused"] and "unstable" in exploded["stability_error"],
          f"an exploding run is paused with the panel hidden: {exploded['stability_error']!r}")
    check(exploded["steps"] < 80, f"it stopped stepping ({exploded['steps']} of 80 steps)")


def paused_reset(args):
    # A reset while paused (tests/viewer/pause_reset.json: Space at frame 3, R at frame 5) shows
    # the reset scene's first state, not an empty tank, though no step follows it.
    scene = os.path.join(args.scenes, "dam_break_2d.json")
    common = [scene, *SIZE, "--no-panel", "--no-overlay"]  # the liquid alone in the screenshots
    first_shot, reset_shot = os.path.join(args.out, "first.png"), os.path.join(args.out, "paused_reset.png")
    run(args, "first_frame", [*common, "--frames", "1", "--screenshot", first_shot])
    r = run(args, "paused_reset", [*common, "--frames", "9", "--screenshot", reset_shot,
                                   "--script", os.path.join(args.scripts, "pause_reset.json")])
    check(r["paused"] and r["steps"] == 0, f"reset and still paused: {r['steps']} steps since the reset")
    first, shown = liquid_pixels(first_shot), liquid_pixels(reset_shot)
    check(first > 1000, f"the first frame shows the column: {first} liquid pixels")
    check(abs(shown - first) < 0.05 * first, f"after the reset the paused view shows it too: {shown} liquid pixels")


def screenshots(args):
    # The S key's screenshots take the next free viewer_NNNN.png of the working folder: two
    # sessions into one folder write two files, and an earlier file is never replaced.
    folder = os.path.join(args.out, "shots")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    earlier = b"an earlier session's screenshot"
    with open(os.path.join(folder, "viewer_0000.png"), "wb") as f:
        f.write(earlier)
    common = [os.path.join(args.scenes, "dam_break_2d.json"), "--frames", "4", *SIZE, "--no-panel",
              "--script", os.path.join(args.scripts, "screenshot.json")]
    run(args, "screenshot_1", common, cwd=folder)
    run(args, "screenshot_2", common, cwd=folder)
    names = sorted(os.listdir(folder))
    check(names == ["viewer_0000.png", "viewer_0001.png", "viewer_0002.png"], f"one new file per session: {names}")
    with open(os.path.join(folder, "viewer_0000.png"), "rb") as f:
        check(f.read() == earlier, "the earlier viewer_0000.png is untouched")
    for name in names[1:]:
        width, height, _ = read_png(os.path.join(folder, name))
        check((width, height) == (320, 240), f"{name} is a 320 x 240 PNG")


def whitewater(args):
    # The 3D dam break with whitewater: paused after its front has hit the box, a screenshot with
    # the spray and foam drawn, W, and one without. The frames differ only where they are: bright
    # pixels added around the box and the far wall (the right half of the view).
    folder = os.path.join(args.out, "whitewater")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    run(args, "whitewater", [os.path.join(args.scenes, "dam_break_3d_whitewater.json"), "--frames", "36", *SIZE,
                             "--steps-per-frame", "8", "--no-panel", "--no-overlay",
                             "--script", os.path.join(args.scripts, "whitewater_toggle.json")], cwd=folder)
    names = sorted(os.listdir(folder))
    check(names == ["viewer_0000.png", "viewer_0001.png"], f"two screenshots: {names}")
    width, height, drawn = read_png(os.path.join(folder, names[0]))
    _, _, hidden = read_png(os.path.join(folder, names[1]))
    brighter = [(x, y) for y in range(height) for x in range(width)
                if sum(drawn[y][4 * x:4 * x + 3]) - sum(hidden[y][4 * x:4 * x + 3]) >= 36]
    darker = [(x, y) for y in range(height) for x in range(width)
              if sum(hidden[y][4 * x:4 * x + 3]) - sum(drawn[y][4 * x:4 * x + 3]) >= 36]
    right = sum(1 for x, _ in brighter if x >= width // 2)
    check(len(brighter) > 100, f"{len(brighter)} pixels brighter with whitewater drawn")
    check(right >= len(brighter) * 9 // 10, f"{right} of them in the right half, where the front hit the box")
    # A bluish bubble over a bright highlight of the surface can darken a pixel, but only there.
    check(len(darker) <= len(brighter) // 20 and all(x >= width // 2 for x, _ in darker),
          f"{len(darker)} pixels darker, all where the whitewater is: W changes nothing else")


def overlay(args):
    # With the panel hidden an overlay shows the scene, the frame rate, the simulated time and
    # PAUSED when paused (tests/viewer/pause_overlay.json: Space at frame 2); it is display only,
    # and O (--no-overlay) or the panel hide it.
    scene = os.path.join(args.scenes, "dam_break_2d.json")
    common = [scene, "--frames", "6", *SIZE]
    script = ["--script", os.path.join(args.scripts, "pause_overlay.json")]
    paused = run(args, "overlay_paused", [*common, "--no-panel", *script])
    lines = paused["overlay"]
    check(paused["paused"] and "PAUSED" in lines, f"paused with the panel hidden, the overlay says so: {lines}")
    check("dam_break_2d.json" in lines, "the overlay names the scene")
    check(any(re.fullmatch(r"\d+\.\d fps, t = \d+\.\d{3} s", line) for line in lines),
          "the overlay shows the frame rate and the simulated time")
    running = run(args, "overlay_running", [*common, "--no-panel"])
    check(running["overlay"] and "PAUSED" not in running["overlay"], f"running, no PAUSED: {running['overlay']}")
    hidden = run(args, "overlay_hidden", [*common, "--no-panel", "--no-overlay"])
    check(hidden["overlay"] == [], "--no-overlay draws none")
    check((hidden["steps"], hidden["time"]) == (running["steps"], running["time"]),
          "the simulation is the same with and without the overlay")
    with_panel = run(args, "overlay_panel", [*common, *script])
    check(with_panel["overlay"] == [] and with_panel["panel_shown"], "with the panel shown there is no overlay")


def panel_fits(r, name):
    w, h, p = r["width"], r["height"], r["panel"]
    check(p["width"] <= 0.4 * w + 0.5 and p["height"] <= h,
          f"{name}: the panel ({p['width']:.0f} x {p['height']:.0f}) is at most 40% of the {w} x {h} window wide and not taller")
    check(0 <= p["x"] and p["x"] + p["width"] <= w + 0.5 and 0 <= p["y"] and p["y"] + p["height"] <= h + 0.5,
          f"{name}: it is inside the window: at ({p['x']:.0f}, {p['y']:.0f})")


def panel_size(args):
    # The panel is sized to the window: at most 40% of its width, never taller, inside it.
    scene = os.path.join(args.scenes, "dam_break_2d.json")
    for w, h in ((320, 240), (640, 480), (1024, 768)):
        r = run(args, f"panel_{w}x{h}", [scene, "--frames", "3", "--width", str(w), "--height", str(h)])
        check((r["width"], r["height"]) == (w, h), f"the window is {w} x {h}")
        panel_fits(r, f"{w} x {h}")


def panel_drag(args):
    # The panel moves by its title bar and folds by its arrow (tests/viewer/panel_drag.json at
    # 640 x 480: dragged 300 px left, folded, dragged 200 px down); the mouse over it does not
    # reach the brush.
    common = [os.path.join(args.scenes, "dam_break_2d.json"), "--frames", "22", "--width", "640", "--height", "480"]
    start = run(args, "panel_start", [*common[:2], "3", *common[3:]])["panel"]
    check(abs(start["x"] + start["width"] - 632) < 1 and abs(start["y"] - 8) < 1 and start["width"] > 150,
          f"the panel starts top right (where the script grabs it): {start}")
    moved = run(args, "panel_drag", [*common, "--script", os.path.join(args.scripts, "panel_drag.json")])
    p = moved["panel"]
    check(abs(p["x"] - (start["x"] - 300)) < 1 and abs(p["y"] - (start["y"] + 200)) < 1,
          f"the title bar drags moved it by (-300, 200): from ({start['x']:.0f}, {start['y']:.0f}) to ({p['x']:.0f}, {p['y']:.0f})")
    check(p["collapsed"], "the click on its arrow folded it (and so it could go 200 px down)")
    check("last_brush" not in moved, "the panel kept the mouse: no brush")


def panel_wrap(args):
    # A long error (a bad edit of the scene, as in bad_reload) wraps to the panel's width, and the
    # panel stays within 40% of the window.
    r = run_with_bad_edit(args, "panel_wrap", ["--width", "640", "--height", "480"])
    check("stiffness" in r["scene_error"], f"the bad edit's error is shown: {r['scene_error']!r}")
    panel_fits(r, "after the error")
    p, line = r["panel"], 13  # ImGui's default font: 13 px lines
    check(p["message_width"] <= p["width"] and p["message_height"] >= 3 * line,
          f"the message is wrapped: {p['message_width']:.0f} x {p['message_height']:.0f} px in a panel "
          f"{p['width']:.0f} px wide")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("mode", choices=["drag", "obstacle", "body", "hit3d", "shallow_water", "camera_reset", "resize", "golden",
                                   "bad_reload", "no_panel", "paused_reset", "screenshots", "overlay", "panel_size",
                                   "panel_drag", "panel_wrap", "whitewater"])
    p.add_argument("--viewer", required=True)
    p.add_argument("--with-xvfb", required=True)
    p.add_argument("--scenes", required=True)
    p.add_argument("--scripts", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--compare")
    p.add_argument("--viewer-arg", action="append", default=[], help="passed to every viewer run (e.g. --3d-path=atlas)")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    globals()[args.mode](args)


if __name__ == "__main__":
    main()
