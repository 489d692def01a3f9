#!/usr/bin/env python3
"""The viewer in a real browser (docs/viewer.md): Debian's Chromium, headless.

On a short quickstart run (5 s): the page opens with every network request refused and no console
error, the interactive page plays, a frame sought to t = 4.5 s shows every robot where positions.bin puts it (pixels checked at
coordinates computed here from positions.bin) and no longer where it was at t = 0; a page whose
data is broken says so (status and console), never a blank page; a video has the frames and
duration asked (ffprobe) and its frame at t matches `--frame t --png`; a truncated or missing file
of the run directory is refused with a message naming it.

Exit 77 (ctest SKIP_RETURN_CODE) only when Chromium is not installed. Standard library only.
"""
import argparse
import json
import os
import pathlib
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

SOURCE = pathlib.Path(__file__).resolve().parents[2]
ROBOT_RGB = (0x1F, 0x6F, 0xB4)  # palette[0] of page/viewer.js: a robot with no state
WIDTH, HEIGHT = 1000, 1000
FAILURES = []


def check(condition, message):
    if not condition:
        FAILURES.append(message)
        print(f"FAIL: {message}")
    return condition


def read_png(path):
    """(width, height, rows of RGB tuples) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, f"{path}: unsupported PNG"
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            corner = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def read_positions(path):
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"SNPOS\0\0\0"
    _, robots, steps, step_ns = struct.unpack("<IIqq", data[8:32])
    return robots, steps, step_ns, data


def position(trace, step, robot):
    robots, _, _, data = trace
    return struct.unpack_from("<dd", data, 32 + (step * robots + robot) * 16)


def to_screen(x, y, arena_w, arena_h):
    """The page's fit (page/viewer.js, fit()): 10-pixel margin, y up, centred."""
    s = min((WIDTH - 20) / arena_w, (HEIGHT - 20) / arena_h)
    ox, oy = (WIDTH - arena_w * s) / 2, (HEIGHT - arena_h * s) / 2
    return ox + x * s, oy + (arena_h - y) * s


def near(rgb, target, tolerance=40):
    return all(abs(a - b) <= tolerance for a, b in zip(rgb, target))


def chromium_command(chromium, profile, extra):
    command = [chromium, "--headless=new", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
               "--user-data-dir=" + str(profile), "--enable-logging=stderr", "--v=0",
               # No network: every name fails to resolve and every proxied request is refused.
               "--host-resolver-rules=MAP * ~NOTFOUND", "--proxy-server=http://127.0.0.1:9",
               "--proxy-bypass-list=<-loopback>"]
    # As `swarmnet view` does (frame_renderer.cpp): Chromium refuses its sandbox to root.
    if os.geteuid() == 0 or os.environ.get("SWARMNET_CHROMIUM_NO_SANDBOX"):
        command.append("--no-sandbox")
    return command + extra


def console_errors(log):
    """Console messages at error level and uncaught exceptions, and failed loads, from the log."""
    bad = []
    for line in log.splitlines():
        if re.search(r":CONSOLE[(:]", line) and ("Uncaught" in line or "rror" in line):
            bad.append(line)
        if "net::ERR" in line or "Failed to load resource" in line:
            bad.append(line)
    return bad


def swarmnet(binary, *args):
    return subprocess.run([binary, *map(str, args)], capture_output=True, text=True, timeout=300)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True, help="the swarmnet command")
    args = parser.parse_args()
    chromium = os.environ.get("SWARMNET_CHROMIUM") or next(
        (shutil.which(n) for n in ("chromium", "chromium-browser", "google-chrome") if shutil.which(n)),
        None)
    if chromium is None:
        print("viewer_browser_test: SKIPPED: Chromium is not installed (apt-get install chromium)")
        return 77

    with tempfile.TemporaryDirectory(prefix="swarmnet-viewer-test-") as work:
        work = pathlib.Path(work)
        run = work / "run"
        done = swarmnet(args.bin, "run", SOURCE / "configs/quickstart.yaml", "--quiet", "--transport",
                        "inproc", "--set", "duration_s=5", "--out", run, "--view")
        if done.returncode != 0:
            sys.exit(f"the run failed: {done.stderr}")
        page = run / "view.html"
        check(page.is_file(), "swarmnet run --view wrote no view.html")
        check((run / "headings.bin").is_file(), "the run wrote no headings.bin")
        # The run directory knows view.html and headings.bin as its own: --overwrite replaces them.
        done = swarmnet(args.bin, "run", SOURCE / "configs/quickstart.yaml", "--quiet", "--transport",
                        "inproc", "--set", "duration_s=5", "--out", run, "--view", "--overwrite")
        check(done.returncode == 0, f"--overwrite refused the run's own files: {done.stderr}")
        html = page.read_text()
        check(not re.search(r"""(src|href)\s*=\s*["']?(https?:)?//""", html),
              "the page refers to something outside itself")

        # 1. A frame at t = 4.5 s, with the network disabled; status and console clean.
        shot = work / "still.png"
        url = f"file://{page}#still&t=4.5&w={WIDTH}&h={HEIGHT}&label=0"
        done = subprocess.run(chromium_command(chromium, work / "profile", [
            f"--window-size={WIDTH},{HEIGHT}", f"--screenshot={shot}", url]),
            capture_output=True, text=True, timeout=120)
        check(done.returncode == 0 and shot.is_file(), f"chromium --screenshot failed: {done.stderr[-2000:]}")
        check(not console_errors(done.stderr), f"console errors: {console_errors(done.stderr)}")
        dom = subprocess.run(chromium_command(chromium, work / "profile", [
            f"--window-size={WIDTH},{HEIGHT}", "--dump-dom", url]),
            capture_output=True, text=True, timeout=120)
        check('<div id="status" hidden="">ok</div>' in dom.stdout,
              "the page did not report ok: " + "".join(re.findall(r'<div id="status"[^<]*', dom.stdout)))
        check(not console_errors(dom.stderr), f"console errors: {console_errors(dom.stderr)}")

        trace = read_positions(run / "positions.bin")
        robots, steps, step_ns = trace[:3]
        step = round(4.5e9 / step_ns)
        scenario = (run / "scenario.resolved.yaml").read_text()
        arena_w = float(re.search(r"width_m:\s*([\d.e+]+)", scenario).group(1))
        arena_h = float(re.search(r"height_m:\s*([\d.e+]+)", scenario).group(1))
        width, height, pixels = read_png(shot)
        check((width, height) == (WIDTH, HEIGHT), f"screenshot is {width}x{height}")
        now = [to_screen(*position(trace, step, r), arena_w, arena_h) for r in range(robots)]
        before = [to_screen(*position(trace, 0, r), arena_w, arena_h) for r in range(robots)]
        at_robot = sum(near(pixels[int(y)][int(x)], ROBOT_RGB) for x, y in now
                       if 0 <= x < WIDTH and 0 <= y < HEIGHT)
        check(at_robot == robots, f"{at_robot} of {robots} robots drawn where positions.bin puts them")
        # Where robots were at t = 0, if they have left (no robot within 8 px now): background.
        left = [(x, y) for x, y in before
                if all((x - a) ** 2 + (y - b) ** 2 > 64 for a, b in now)]
        stale = sum(near(pixels[int(y)][int(x)], ROBOT_RGB) for x, y in left)
        check(len(left) >= robots // 2, f"only {len(left)} robots moved far enough to test the seek")
        check(stale == 0, f"{stale} of {len(left)} robots still drawn at their t = 0 place")

        # The interactive page plays (play=1; virtual time drives its animation frames).
        dom = subprocess.run(chromium_command(chromium, work / "profile", [
            "--window-size=1100,720", "--virtual-time-budget=3000",
            "--run-all-compositor-stages-before-draw", "--dump-dom", f"file://{page}#t=0&play=1"]),
            capture_output=True, text=True, timeout=120)
        clock = re.search(r'<span id="clock">([\d.]+) /', dom.stdout)
        check(clock is not None and float(clock.group(1)) > 0, "the interactive page did not play: "
              + (clock.group(0) if clock else "no clock"))
        check('<div id="status" hidden="">ok</div>' in dom.stdout, "the interactive page failed")
        check(not console_errors(dom.stderr), f"console errors: {console_errors(dom.stderr)}")

        # A run with sampled series: the chart offers each, and draws the one picked.
        with open(run / "series.csv", "w") as f:
            f.write("time_ns,robot,series,value\n")
            for step in range(50):
                for robot in range(3):
                    f.write(f"{step * 100000000},{robot},\"link, share\",{0.5 + 0.01 * robot}\n")
                f.write(f"{step * 100000000},,events_done,{step}\n")
        series_page = work / "series.html"
        done = swarmnet(args.bin, "view", run, "--out", series_page)
        check(done.returncode == 0, f"swarmnet view of a run with series.csv failed: {done.stderr}")
        dom = subprocess.run(chromium_command(chromium, work / "profile", [
            "--window-size=1100,720", "--virtual-time-budget=1000", "--dump-dom",
            f"file://{series_page}#t=2"]), capture_output=True, text=True, timeout=120)
        check('<option value="0">Series: events_done (world)</option>' in dom.stdout and
              '<option value="1">Series: link, share</option>' in dom.stdout,
              "the chart does not offer the sampled series: "
              + "".join(re.findall(r'<select id="chart-pick".*?</select>', dom.stdout, re.S)))
        check('<div id="status" hidden="">ok</div>' in dom.stdout, "the page with series failed")
        check(not console_errors(dom.stderr), f"console errors: {console_errors(dom.stderr)}")
        (run / "series.csv").unlink()

        # 2. A page whose data is broken: an error shown and on the console, never a blank page.
        broken = work / "broken.html"
        broken.write_text(re.sub(r'(<script type="application/json" id="meta">).*?(</script>)',
                                 r"\1{not json\2", html, count=1, flags=re.S))
        dom = subprocess.run(chromium_command(chromium, work / "profile", [
            "--dump-dom", f"file://{broken}#still"]), capture_output=True, text=True, timeout=120)
        check('id="status" hidden="">error:' in dom.stdout, "a broken page did not report its error")
        check(console_errors(dom.stderr), "a broken page's error did not reach the console log")

        # 3. The video: frames and duration; its frame at t = 2.5 s matches --frame 2.5 --png.
        video = work / "run.mp4"
        done = swarmnet(args.bin, "view", run, "--out", work / "v.html", "--video", video,
                        "--fps", 10, "--from", 1, "--to", 4, "--size", "640x480")
        check(done.returncode == 0, f"view --video failed: {done.stderr}")
        probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                                "-show_entries", "stream=nb_read_frames,duration,width,height",
                                "-of", "json", str(video)], capture_output=True, text=True)
        stream = json.loads(probe.stdout)["streams"][0]
        check(int(stream["nb_read_frames"]) == 30, f"video has {stream['nb_read_frames']} frames, not 30")
        check(abs(float(stream["duration"]) - 3.0) < 1e-6, f"video lasts {stream['duration']} s, not 3")
        check((stream["width"], stream["height"]) == (640, 480), "video size is not 640x480")
        figures = {}
        for t in (2.5, 1.0):
            png = work / f"frame-{t}.png"
            done = swarmnet(args.bin, "view", run, "--out", work / "v.html", "--frame", t,
                            "--png", png, "--size", "640x480")
            check(done.returncode == 0, f"view --frame failed: {done.stderr}")
            figures[t] = read_png(png)[2]
        extracted = work / "from-video.png"
        subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", str(video), "-vf",
                        r"select=eq(n\,15)", "-frames:v", "1", str(extracted)], check=True)
        from_video = read_png(extracted)[2]

        def difference(a, b):
            total = sum(abs(p - q) for ra, rb in zip(a, b) for pa, pb in zip(ra, rb)
                        for p, q in zip(pa, pb))
            return total / (640 * 480 * 3)

        same, other = difference(from_video, figures[2.5]), difference(from_video, figures[1.0])
        print(f"video frame 15 vs --frame 2.5: {same:.2f}; vs --frame 1.0: {other:.2f} (mean |diff|)")
        check(same < 3.0 and same < other / 2, "the video's frame at 2.5 s does not match the PNG")

        # 4. A truncated or missing file is refused, naming it; no page is written.
        for damage, name in (("truncate", "positions.bin"), ("remove", "summary.json"),
                             ("garble", "packets.csv")):
            copy = work / f"damaged-{damage}"
            shutil.copytree(run, copy, ignore=shutil.ignore_patterns("view.html"))
            target = copy / name
            if damage == "truncate":
                os.truncate(target, target.stat().st_size - 7)
            elif damage == "remove":
                target.unlink()
            else:
                with open(target, "a") as out:
                    out.write("12,deliver,3\n")
            done = swarmnet(args.bin, "view", copy)
            check(done.returncode != 0, f"a run directory with {name} {damage}d was accepted")
            check(name in done.stderr, f"the error does not name {name}: {done.stderr!r}")
            check(not (copy / "view.html").exists(), f"a page was written for a broken {name}")
            print(f"{damage} {name}: {done.stderr.strip()}")

    if FAILURES:
        print(f"viewer_browser_test: {len(FAILURES)} check(s) failed")
        return 1
    print("viewer_browser_test: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
