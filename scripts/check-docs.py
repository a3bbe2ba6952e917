#!/usr/bin/env python3
"""The documentation's commands run and its links resolve.

Usage: scripts/check-docs.py PENUMBRA [--links-only] [--gallery]

Reads README.md and every docs/**/*.md:
- every relative link and image (Markdown and <img src>) names a file that exists, and a `#anchor`
  names a heading of its page;
- every fenced block carries a language (docs/cli.md, generated, excepted), so that no command
  hides in an untagged block; `sh` blocks are commands;
- each `sh` block runs with bash (`set -euo pipefail`) in a scratch copy of the tree, unless its
  fence reads `sh no-ci: REASON` (at most 10 such blocks, each with its reason);
- in README.md, every inline command of the gallery's captions (a code span starting
  `./build/penumbra`) runs too.

Commands run at small sizes: `./build/penumbra` there is a wrapper that replaces the image size
with 64x36, caps path counts, frames, strands and sky maps (SMALL below) and shortens the long defaults of
eval, stability and bench (SHORT); a doc that writes a size documents the full-size run. A command naming ../shared/assets is skipped, and says so, where the
assets are absent (a fresh CI machine has none); the block's other commands still run.

--links-only checks the links and fences alone; --gallery prints the gallery's commands, one a line
(bench/run.sh gallery renders them at full size).
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
SHELL = {"sh"}
MAX_NO_CI = 10
FENCE = re.compile(r"^(\s*)```(.*)$")
LINK = re.compile(r"!?\[(?:[^\]]|\][^(])*?\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
IMG = re.compile(r"<img[^>]*\ssrc=\"([^\"]+)\"")
CODE_SPAN = re.compile(r"`(\./build/penumbra [^`]+)`")
GALLERY = re.compile(r"^## Gallery", re.M)
# The wrapper's caps: option -> the largest value the doc test runs.
SMALL = {"--spp": 16, "--frames": 4, "--warmup": 1, "--strands": 2000, "--reference-max-spp": 64,
         "--sequence": 3, "--shadow-res": 512, "--rsm-res": 256, "--lpv-rsm-res": 512, "--lpv-vpl-res": 128,
         "--sky-maps": 8}
SIZE = ["--width", "64", "--height", "36"]
SIZED = {"render", "bench", "stability", "reference", "eval", "view"}
# Defaults of a long run, given where the command leaves them out: frames per technique and still frames.
SHORT = {"eval": {"--frames": "2"}, "stability": {"--warmup": "2", "--reference-max-spp": "32"},
         "bench": {"--frames": "4", "--warmup": "1"}}


def pages():
    return [ROOT / "README.md"] + sorted((ROOT / "docs").rglob("*.md"))


def slug(heading):
    s = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return s.replace(" ", "-")


def anchors(page):
    seen, out = {}, set()
    in_fence = False
    for line in page.read_text(encoding="utf-8").splitlines():
        if FENCE.match(line):
            in_fence = not in_fence
        if in_fence or not line.startswith("#"):
            continue
        s = slug(line.lstrip("#"))
        n = seen.get(s, 0)
        seen[s] = n + 1
        out.add(s if n == 0 else f"{s}-{n}")
    return out


def blocks(page):
    """(line, info, text) of each fenced block."""
    out, lines, i = [], page.read_text(encoding="utf-8").splitlines(), 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        start, info, body = i + 1, m.group(2).strip(), []
        i += 1
        while i < len(lines) and not FENCE.match(lines[i]):
            body.append(lines[i])
            i += 1
        out.append((start, info, "\n".join(body)))
        i += 1
    return out


def prose(page):
    """The page without its fenced blocks."""
    kept, in_fence = [], False
    for line in page.read_text(encoding="utf-8").splitlines():
        if FENCE.match(line):
            in_fence = not in_fence
            continue
        kept.append("" if in_fence else line)
    return kept


def check_links(errors):
    for page in pages():
        rel = page.relative_to(ROOT)
        for n, line in enumerate(prose(page), 1):
            for target in LINK.findall(line) + IMG.findall(line):
                if re.match(r"^[a-z]+:", target):
                    continue
                path, _, anchor = target.partition("#")
                dest = (page.parent / path).resolve() if path else page
                if not dest.exists():
                    errors.append(f"{rel}:{n}: link to {target}: no such file")
                elif anchor and dest.suffix == ".md" and anchor not in anchors(dest):
                    errors.append(f"{rel}:{n}: link to {target}: no heading '#{anchor}' there")


def gallery_commands():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    m = GALLERY.search(text)
    if not m:
        return []
    section = text[m.end():]
    end = re.search(r"^## ", section, re.M)
    return CODE_SPAN.findall(section[:end.start()] if end else section)


def commands(errors):
    """(where, script) of each command to run; fence errors go to `errors`."""
    out, no_ci = [], []
    for page in pages():
        rel = page.relative_to(ROOT)
        for line, info, body in blocks(page):
            lang, _, rest = info.partition(" ")
            if not lang:
                if rel != pathlib.Path("docs/cli.md"):
                    errors.append(f"{rel}:{line}: a fenced block without a language (sh, text, json, cmake, cpp ...)")
                continue
            if lang not in SHELL:
                continue
            if rest.startswith("no-ci"):
                reason = rest[len("no-ci"):].lstrip(":").strip()
                if not reason:
                    errors.append(f"{rel}:{line}: 'no-ci' without its reason")
                no_ci.append(f"{rel}:{line}")
                continue
            out.append((f"{rel}:{line}", body))
    out += [("README.md gallery", c) for c in gallery_commands()]
    if len(no_ci) > MAX_NO_CI:
        errors.append(f"{len(no_ci)} blocks tagged no-ci, more than {MAX_NO_CI}: {' '.join(no_ci)}")
    print(f"check-docs: {len(out)} commands to run, {len(no_ci)} blocks tagged no-ci")
    return out


WRAPPER = """#!/usr/bin/env python3
# The doc test's penumbra: the real one at small sizes (scripts/check-docs.py).
import os, sys
real, small, size, sized, short = {real!r}, {small!r}, {size!r}, {sized!r}, {short!r}
args, out, i = sys.argv[1:], [], 0
while i < len(args):
    flag, _, inline = args[i].partition("=")
    if flag in ("--width", "--height") and args[0] in sized:
        i += 1 if inline else 2
        continue
    if flag in small:
        value = inline or (args[i + 1] if i + 1 < len(args) else "")
        try:
            value = str(min(int(value), small[flag]))
        except ValueError:
            pass
        out += [flag, value]
        i += 1 if inline else 2
        continue
    out.append(args[i])
    i += 1
if args and args[0] in sized and "--suite" not in args:
    out += size
if args:
    given = {{a.partition("=")[0] for a in args}}
    for flag, value in short.get(args[0], {{}}).items():
        if flag not in given:
            out += [flag, value]
    if "hair" in args and "--strands" not in given:  # the built-in hair scene's 25000 strands
        out += ["--strands", str(small["--strands"])]
    if args[0] in ("render", "bench", "stability"):  # maps of 2048^2 are most of a small frame's time
        if "--shadow-res" not in given:
            out += ["--shadow-res", str(small["--shadow-res"])]
        if "lpv" in args and "--lpv-rsm-res" not in given:
            out += ["--lpv-rsm-res", str(small["--lpv-rsm-res"])]
    if args[0] in ("render", "bench", "stability", "view") and "--sky-maps" not in given:
        out += ["--sky-maps", str(small["--sky-maps"])]  # the sky's 64 views of a large scene, on a CPU device
os.execv(real, [real] + out)
"""


def scratch_tree(tmp, penumbra):
    """A copy of the tree's layout: the source's folders linked, build/penumbra the small wrapper,
    ../shared the source's neighbour."""
    repo = tmp / "repo"
    repo.mkdir()
    for entry in ROOT.iterdir():
        if entry.name not in ("build", ".git"):
            (repo / entry.name).symlink_to(entry)
    (repo / "build").mkdir()
    wrapper = repo / "build" / "penumbra"
    wrapper.write_text(WRAPPER.format(real=str(pathlib.Path(penumbra).resolve()), small=SMALL, size=SIZE,
                                      sized=sorted(SIZED), short=SHORT))
    wrapper.chmod(0o755)
    if (ROOT.parent / "shared").exists():
        (tmp / "shared").symlink_to(ROOT.parent / "shared")
    return repo


def without_assets(script):
    """The script without its commands on ../shared/assets (lines continued by a backslash, && or | are one)."""
    kept, command = [], []
    for line in script.splitlines():
        command.append(line)
        if line.rstrip().endswith(("\\", "&&", "||", "|")):
            continue
        if "../shared/assets" in "\n".join(command):
            print("  skip (no ../shared/assets): " + command[0][:90])
        else:
            kept += command
        command = []
    return "\n".join(kept + command)


def run(cmds, penumbra, errors):
    # CHECK_DOCS_NO_ASSETS=1 runs as a machine without them would (CI's time).
    assets = (ROOT.parent / "shared" / "assets").is_dir() and not os.environ.get("CHECK_DOCS_NO_ASSETS")
    with tempfile.TemporaryDirectory(prefix="penumbra-docs-") as t:
        repo = scratch_tree(pathlib.Path(t), penumbra)
        env = dict(os.environ, PATH=f"{repo / 'build'}:{os.environ['PATH']}")
        for where, script in cmds:
            if not assets:
                script = without_assets(script)
                if not script.strip():
                    print(f"skip {where}: no ../shared/assets next to the source tree")
                    continue
            print(f"run  {where}: {script.splitlines()[0][:100]}", flush=True)
            start = time.monotonic()
            try:
                r = subprocess.run(["bash", "-c", "set -euo pipefail\n" + script], cwd=repo, env=env,
                                   capture_output=True, text=True, timeout=600)
            except subprocess.TimeoutExpired:
                errors.append(f"{where}: ran past 600 s")
                continue
            print(f"     {time.monotonic() - start:.1f} s, exit {r.returncode}", flush=True)
            if r.returncode != 0:
                tail = "\n    ".join((r.stdout + r.stderr).strip().splitlines()[-8:])
                errors.append(f"{where}: exit {r.returncode}\n    {tail}")


def main():
    args = sys.argv[1:]
    if "--gallery" in args:
        print("\n".join(gallery_commands()))
        return 0
    errors = []
    check_links(errors)
    cmds = commands(errors)
    if "--links-only" not in args:
        if not args:
            sys.exit(__doc__)
        run(cmds, args[0], errors)
    for e in errors:
        print("check-docs: " + e)
    if errors:
        print(f"check-docs: {len(errors)} problems")
        return 1
    print("check-docs: every link resolves, every command ran")
    return 0


if __name__ == "__main__":
    sys.exit(main())
