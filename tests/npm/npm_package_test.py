"""The npm package `flipcheck` as an engine's test suite meets it (docs/flipcheck.md, "In your
engine's tests"): npm/build.sh makes BUILD/npm/flipcheck-VERSION.tgz (under 3 MB, no runtime
dependencies); an empty temporary project gets it and cannon-es (packed from web/node_modules,
the version web/package-lock.json pins) installed offline, with an empty npm cache and no
network; there

- examples/flipcheck-npm/ runs under node's own test runner (`node --test`): cannon-es fails
  every scenario and never turns the book over;
- cannon-es' motion in every scenario, judged by the package as arrays and as CSV text, equals
  `bookspin flipcheck judge` of the same motion file in every column (numbers to 1e-12
  relative, or 1e-13 where a measure is round-off), and `npx flipcheck judge` prints the
  command's lines (the numbers to their printed digits, round-off aside) and writes its CSV;
- every JavaScript engine mode the league runs (web/flipcheck-engines.mjs, eleven) in the three
  shorter scenarios: `npx flipcheck judge` of its motion files as the command line's judge;
- `npx flipcheck export` writes the command's scenario JSON byte for byte and its exact motion
  to 1e-12;
- a seeded property of the judge at this door (tests/npm/judge_property.mjs) and a scenario JSON
  fuzzer (fields missing, mistyped, out of range or hostile: one line, exit 2, nothing outside -o);
- bad input: the command line's one line (an Error's message in the API, on stderr with exit
  status 2 from npx), and an unknown scenario exit 2.

Skipped (exit 77) where em++, node, npm or the league's packages (web/node_modules) are missing; a failure under
CI=true. Usage: npm_package_test.py BOOKSPIN SOURCE_DIR BUILD_DIR"""
import csv
import hashlib
import io
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tarfile
import tempfile

SKIP = 77


def missing(what):
    if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
        print(f"FAIL: {what} (CI=true: this test must run; scripts/install-deps.sh installs it)")
        sys.exit(1)
    print(f"SKIP: {what} (scripts/install-deps.sh installs it)")
    sys.exit(SKIP)


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def run(args, env=None, cwd=None, expect=0):
    """Runs args; fail() unless it exits `expect` (3: judge's FAIL, docs/flipcheck.md "In a CI
    job"; 2: bad input)."""
    done = subprocess.run([str(a) for a in args], env=env, cwd=cwd, capture_output=True,
                          text=True, timeout=600)
    if done.returncode != expect:
        fail(f"{args} exited {done.returncode}, expected {expect}:\n{done.stdout}{done.stderr}")
    return done


def read_csv(text):
    rows = list(csv.reader(io.StringIO(text)))
    return [dict(zip(rows[0], r)) for r in rows[1:]]


def same_number(a, b):
    return a == b or abs(a - b) <= max(1e-12 * max(abs(a), abs(b)), 1e-13)


def same_row(cli, got, what):
    """A judgement row of the command line's CSV (text cells) against the package's object."""
    for column, cell in cli.items():
        value = got[column]
        if column in ("scenario", "verdict", "failures", "motion", "version", "scenario_sha256"):
            ok = (value or "") == cell
        elif cell == "":
            ok = value is None
        else:
            ok = same_number(float(cell), float(value))
        if not ok:
            fail(f"{what}: {column}: the command line has {cell!r}, the package {value!r}")


NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?")


def same_line(a, b):
    """The lines the command prints: the words equal, each number to its 3 significant digits,
    or both round-off (below 1e-12: an engine that keeps E to round-off, natively and in
    WebAssembly, rounds differently)."""
    if NUMBER.sub("#", a) != NUMBER.sub("#", b):
        return False
    for x, y in zip(NUMBER.findall(a), NUMBER.findall(b)):
        x, y = float(x), float(y)
        if not (x == y or abs(x - y) <= 6e-3 * max(abs(x), abs(y)) or max(abs(x), abs(y)) < 1e-12):
            return False
    return True


def error_line(stderr, prefix):
    lines = [l for l in stderr.splitlines() if l.startswith(prefix)]
    if len(lines) != 1:
        fail(f"expected one line starting {prefix!r}: {stderr}")
    return lines[0][len(prefix):]


DELETE = object()
# (field, value, what the one line must hold; None: taken as written, judged)
HOSTILE = [
    ("scenario", DELETE, "scenario: missing"), ("scenario", 3, "scenario: expected a name"),
    ("scenario", "../escaped", "scenario name \"../escaped\""),
    ("scenario", "a/b", "scenario name"), ("scenario", "a\u0000b", "byte 0x00"),
    ("scenario", "a\nb", "byte 0x0a"), ("scenario", "..", "scenario name"),
    ("principal_moments", DELETE, "principal_moments: missing"),
    ("principal_moments", [1, 2], "principal_moments: expected an array of 3 numbers, got 2"),
    ("principal_moments", "1,2,3", "principal_moments: expected an array of 3 numbers"),
    ("principal_moments", [1, None, 3], "principal_moments[1]: expected a number"),
    ("principal_moments", [1, 0, 3], "principal_moments[1]"),
    ("mass", DELETE, "mass: missing"), ("mass", -1, "mass: -1"), ("mass", "1", "mass: expected a number"),
    ("q0", [0, 1, 0, 0], "q0: (0, 1, 0, 0): every scenario starts at the identity"),
    ("q0", [1, 0], "q0: expected an array of 4 numbers"),
    ("omega0_world", [9, 9, 9], "omega0_world: (9, 9, 9) is not omega0_body"),
    ("omega0_body", DELETE, None),  # omega0_world alone is the start: judged
    ("units", DELETE, None), ("q0", [-1, 0, 0, 0], None),  # the identity either sign
    ("omega0_body", [1e200, 2, 3], "omega0_body[0]: 1e+200 is beyond"),
    ("omega0_body", [0, 0, 0], "the body is at rest"),
    ("dt", 1e300, "dt: 1e+300 over 500 steps"), ("dt", 0, "dt: 0"), ("dt", "0.01", "dt: expected a number"),
    ("dt", DELETE, "dt: missing"),
    ("steps", 2.5, "steps: 2.5 is not a whole number"), ("steps", 1e12, "steps: 1000000000000 must be"),
    ("steps", 2e7, "steps: 20000000 must be"), ("steps", -3, "steps: -3 must be"),
    ("steps", DELETE, "steps: missing"),
]


def fuzz_scenarios(npx, env, project, tmp, source):
    base = json.loads((project / "node_modules" / "flipcheck" / "scenarios" /
                       "mujoco-test-box.json").read_text())
    room = tmp / "fuzz"
    room.mkdir()
    exact = room / "exact"
    run(npx + ["export", "mujoco-test-box", "-o", exact], env, cwd=project)
    motion = exact / "mujoco-test-box-exact.csv"
    # The stock scenario as a file, then with the fields it may have written its own way.
    for k, (field, value, said) in enumerate([(None, None, None)] + HOSTILE):
        spec = dict(base)
        if field is not None:
            if value is DELETE:
                del spec[field]
            else:
                spec[field] = value
                if field == "omega0_body":  # the start in both frames, as export writes it
                    spec["omega0_world"] = value
        file = room / f"case{k}.json"
        file.write_text(json.dumps(spec))
        out = room / f"out{k}"
        for command in (["export", file, "-o", out], ["judge", file, motion, "-o", out]):
            done = run(npx + command, env, cwd=project, expect=0 if said is None else 2)
            if said is None:
                continue
            lines = done.stderr.splitlines()
            if len(lines) != 1 or not lines[0].startswith("flipcheck: error: ") or said not in lines[0]:
                fail(f"{field} = {value!r}: npx {command[0]} said {done.stderr!r}, expected one "
                     f"line holding {said!r}")
            if out.exists():
                fail(f"{field} = {value!r}: npx {command[0]} wrote {sorted(out.rglob('*'))}")
        outside = sorted(p.name for p in room.iterdir()
                         if not re.fullmatch(r"case\d+\.json|out\d+|exact", p.name))
        outside += sorted(p.name for p in tmp.iterdir() if "escaped" in p.name)
        if outside:
            fail(f"{field} = {value!r}: written outside -o: {outside}")
    print(f"scenario JSON fuzzer: {len(HOSTILE)} fields changed, each one line and exit 2 or judged")
    # A motion file whose name holds a line break: one row of the judgement CSV, its name
    # whole in its cell (the rows ran together).
    odd = room / "two\nlines.csv"
    shutil.copy(motion, odd)
    run(npx + ["judge", "mujoco-test-box", odd, motion, "-o", room / "odd"], env, cwd=project)
    rows = read_csv((room / "odd" / "mujoco-test-box-judge.csv").read_text())
    if [r["motion"] for r in rows] != ["two\nlines.csv", motion.name] or \
            [r["verdict"] for r in rows] != ["pass", "pass"]:
        fail(f"a name with a line break: the judgement CSV reads {rows}")
    shutil.rmtree(room / "odd")
    odd.unlink()


def bad_scenario_texts(base):
    """(what, text): scenario files that are no scenario, each refused by a field, by its JSON or
    by what it holds (text, or bytes: a file saved as UTF-16); a field changed is given again last (a key given twice: the last counts,
    as JSON.parse and Python's json read it)."""
    good = json.dumps(base)

    def again(field, raw):
        return good[:-1] + f', "{field}": {raw}}}'

    return [
        ("not JSON", '{"scenario": }'),
        ("JSON null after a byte-order mark", "\ufeffnull"),
        ("an array", "[1, 2, 3]"),
        ("a number", "3"),
        ("more after the value", good + " x"),
        ("nested too deep", "[" * 70 + "]" * 70),
        ("a field nested too deep", again("extra", "[" * 70 + "]" * 70)),
        ("saved as UTF-16", ("\ufeff" + good).encode("utf-16-le")),
        ("saved as UTF-16, big-endian", ("\ufeff" + good).encode("utf-16-be")),
        ("no name", json.dumps({k: v for k, v in base.items() if k != "scenario"})),
        ("a name of escapes", again("scenario", r'"caf\u00e9 \ud83d\ude00"')),
        ("a name holding NUL", again("scenario", r'"a\u0000b"')),
        ("an unknown escape", again("scenario", r'"a\qb"')),
        ("a raw tab in a string", again("scenario", '"a\tb"')),
        ("a name that is a number", again("scenario", "3")),
        ("a negative mass", again("mass", "-1")),
        ("a mass beyond a double", again("mass", "1e999")),
        ("a time step of -0", again("dt", "-0")),
        ("steps not whole", again("steps", "2.5")),
        ("a moment null", again("principal_moments", "[1, null, 3]")),
        ("two moments", again("principal_moments", "[1, 2]")),
        ("q0 turned", again("q0", "[0, 1, 0, 0]")),
        ("the start at rest, -0", again("omega0_body", "[-0, 0, 0]")),
        ("omega0_world alone, at rest",
         json.dumps({k: v for k, v in base.items() if k != "omega0_body"})[:-1] +
         ', "omega0_world": [0, 0, 0]}'),
    ]


def scenario_refusals_at_every_door(npx, env, project, tmp, bookspin, build, source):
    """Bad scenario JSON files (bad_scenario_texts) refused by the command line, the Python
    module, `npx flipcheck`, the package's judge() and the engines' runner
    (web/flipcheck-engines.mjs, nothing written) in the same words: one reader
    (analysis::scenario_from_json) behind every door. judge() of the file's object (JSON.parse)
    names it "scenario JSON" where the others name the file; an array or JSON null is no object,
    which that door refuses in its own words."""
    base = json.loads((project / "node_modules" / "flipcheck" / "scenarios" /
                       "mujoco-test-box.json").read_text())
    room = tmp / "doors"
    room.mkdir()
    run(npx + ["export", "mujoco-test-box", "-o", room / "exact"], env, cwd=project)
    motion = room / "exact" / "mujoco-test-box-exact.csv"
    cases = bad_scenario_texts(base)
    files = []
    for k, (_, text) in enumerate(cases):
        files.append(room / f"case{k}.json")
        if isinstance(text, bytes):
            files[-1].write_bytes(text)
        else:
            files[-1].write_text(text, encoding="utf-8")
    module = sorted((build / "python").glob("bookspin*.so"))
    python = None
    if not module:
        if os.environ.get("CI", "").lower() in ("1", "true", "yes"):
            fail("the Python module BUILD/python/bookspin*.so is not built")
        print("scenario refusals: the Python module is not built; its door left out")
    else:
        said = run([sys.executable, "-c", (
            "import bookspin, json, sys\n"
            "out = {}\n"
            "for f in sys.argv[1:]:\n"
            "    try:\n"
            "        bookspin.flipcheck.judge(f, [0.0], [[1.0, 0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]])\n"
            "        out[f] = None\n"
            "    except bookspin.Error as e:\n"
            "        out[f] = str(e)\n"
            "print(json.dumps(out))\n"), *files],
            env={**env, "PYTHONPATH": str(build / "python")})
        python = json.loads(said.stdout)
    (project / "doors.mjs").write_text(
        'import { readFileSync } from "node:fs";\n'
        'import { judge } from "flipcheck";\n'
        "const out = {};\n"
        "for (const f of process.argv.slice(2)) {\n"
        "  let json;\n"
        "  try { json = JSON.parse(readFileSync(f, 'utf8').replace(/^\\uFEFF/, '')); } catch { continue; }\n"
        "  if (typeof json !== 'object' || json === null || Array.isArray(json)) continue;\n"
        "  try { judge(json, { t: [0], q: [1, 0, 0, 0], omegaWorld: [0, 0, 1] }); out[f] = null; }\n"
        "  catch (e) { out[f] = e.message; }\n"
        "}\n"
        "console.log(JSON.stringify(out));\n")
    api = json.loads(run(["node", "doors.mjs", *files], env, cwd=project).stdout)
    for (what, _), file in zip(cases, files):
        cli = error_line(run([bookspin, "flipcheck", "judge", file, motion, "-o", room / "cli"],
                             expect=2).stderr, "bookspin: error: ")
        ours = error_line(run(npx + ["judge", file, motion, "-o", room / "npx"], env,
                              cwd=project, expect=2).stderr, "flipcheck: error: ")
        if ours != cli:
            fail(f"{what}: the command line says {cli!r}, npx {ours!r}")
        if python is not None and python[str(file)] != cli:
            fail(f"{what}: the command line says {cli!r}, Python {python[str(file)]!r}")
        if str(file) in api:
            want = cli.replace(str(file), "scenario JSON")
            # Too deep: the same words, at a line and column in a file, at a key path in an
            # object ("… nested more than 64 deep at extra[0][0]…").
            deep = " nested more than 64 deep at "
            if deep in want and api[str(file)].split(deep)[0] == want.split(deep)[0]:
                want = api[str(file)]
            if api[str(file)] != want:
                fail(f"{what}: judge() of the file's object says {api[str(file)]!r}, the command "
                     f"line {want!r}")
        elif not cli.startswith(f"{file}: "):
            fail(f"{what}: judge() could not take it, yet the command line names no file: {cli!r}")
        # The engines' runner (web/flipcheck-engines.mjs) reads it with the package's reader.
        said = run(["node", source / "web" / "flipcheck-engines.mjs", "--only", "cannon-es",
                    "--flipcheck", build / "npm" / "package", room / "engines", file], expect=2)
        runner = error_line(said.stderr, "flipcheck-engines: ")
        if runner != cli or said.stdout:
            fail(f"{what}: the command line says {cli!r}, the engines' runner {runner!r}")
        if (room / "cli").exists() or (room / "npx").exists() or (room / "engines").exists():
            fail(f"{what}: a refused scenario wrote a judgement or a motion")
    doors = "the command line, Python, npx, judge() and the engines' runner" \
        if python is not None else "the command line, npx, judge() and the engines' runner"
    print(f"scenario refusals: {len(cases)} bad scenario files, one line each in the same words "
          f"at {doors}")


def turned_from(csv_text, step):
    """The exact motion's CSV with every row from `step` on turned (qx negated): a broken
    engine."""
    lines = csv_text.splitlines()
    qx = lines[0].split(",").index("qx")
    for i in range(1 + step, len(lines)):
        cells = lines[i].split(",")
        cells[qx] = cells[qx][1:] if cells[qx].startswith("-") else "-" + cells[qx]
        lines[i] = ",".join(cells)
    return "\n".join(lines) + "\n"


def ci_example(npx, env, project, tmp, bookspin, source):
    """docs/flipcheck.md, "In a CI job": examples/flipcheck-ci/'s shell step and node test run
    as an engine's CI runs them, on the exact motion (pass: exit 0) and on it turned from step
    100 on (fail: the step exits 3, node --test 1, each with the judge's FAIL line); the command
    line's judge exits 3 on it too."""
    name = "book-intermediate-0.05"
    kit = tmp / "ci-kit"
    run([bookspin, "flipcheck", "export", source / "scenes" / "flipcheck" / f"{name}.toml", "-o", kit])
    exact = kit / f"{name}-exact.csv"
    broken = tmp / "broken.csv"
    broken.write_text(turned_from(exact.read_text(), 100))
    for file in sorted((source / "examples" / "flipcheck-ci").iterdir()):
        shutil.copy(file, project / file.name)
    # npx --no-install finds the package in the project's node_modules/.bin.
    path_env = dict(env, PATH=f"{project / 'node_modules' / '.bin'}:{env['PATH']}")
    for motion, status, node_status in ((exact, 0, 0), (broken, 3, 1)):
        step = run(["sh", "ci-step.sh", motion], path_env, cwd=project, expect=status)
        if status and f"{name} {motion}: FAIL (" not in step.stdout:
            fail(f"ci-step.sh on a broken motion printed {step.stdout!r}")
        if not status and "passes" not in step.stdout:
            fail(f"ci-step.sh on the exact motion printed {step.stdout!r}")
        tested = run(["node", "--test", "motion.test.mjs"], dict(env, MOTION=str(motion)),
                     cwd=project, expect=node_status)
        if status and f"{name} broken.csv: FAIL (" not in tested.stdout:
            fail(f"motion.test.mjs on a broken motion printed {tested.stdout!r}")
        run([bookspin, "flipcheck", "judge", kit / f"{name}.json", motion, "-o", tmp / "ci-cli"],
            expect=status)
    print("examples/flipcheck-ci: the shell step and the node test pass the exact motion and "
          "fail a broken one (exit 3, node --test 1)")


def round_trips(npx, env, project, tmp, bookspin, source):
    """Every file `bookspin flipcheck export` writes judged by npx: each scenario's JSON with its
    exact motion at every step, and every k-th step with and without the last, k = 7 (which
    divides no scenario's steps) or, where rows 7 steps apart are refused as too far apart, the
    stride the refusal names as safe: all pass, exit 0."""
    kit = tmp / "trip-kit"
    run([bookspin, "flipcheck", "export", *sorted((source / "scenes" / "flipcheck").glob("*.toml")),
         "-o", kit])
    for spec in sorted(kit.glob("*.json")):
        name = spec.stem
        lines = (kit / f"{name}-exact.csv").read_text().splitlines()

        def thinned(k):
            every = [lines[0]] + lines[1::k]
            (tmp / f"{name}-every.csv").write_text("\n".join(every) + "\n")
            last = every + ([lines[-1]] if (len(lines) - 2) % k else [])
            (tmp / f"{name}-every-last.csv").write_text("\n".join(last) + "\n")
            return subprocess.run([str(a) for a in npx + [
                "judge", spec, kit / f"{name}-exact.csv", tmp / f"{name}-every.csv",
                tmp / f"{name}-every-last.csv", "-o", tmp / "trip"]], env=env, cwd=project,
                capture_output=True, text=True, timeout=600)

        done = thinned(7)
        named = re.search(r"write a row at least every (\d+) steps", done.stderr)
        if done.returncode == 2 and named:
            done = thinned(int(named.group(1)))
        if done.returncode != 0 or done.stdout.count(": PASS: ") != 3:
            fail(f"{name}: npx judge of the exported files exited {done.returncode}:\n"
                 f"{done.stdout}{done.stderr}")
    print("npx flipcheck judge takes every exported JSON and passes its exact motion at every "
          "step and every 7th, with and without the last")


def export_checks_every_scenario_first(npx, env, project, tmp):
    """npx flipcheck export of a good scenario and a bad one writes nothing (it wrote the good
    one, then refused the bad one): the earlier files keep their bytes."""
    out = tmp / "staged"
    out.mkdir()
    earlier = {"mujoco-test-box.json": "earlier json\n", "mujoco-test-box-exact.csv": "earlier csv\n"}
    for name, text in earlier.items():
        (out / name).write_text(text)
    bad = tmp / "bad-scenario.json"
    bad.write_text(json.dumps({"scenario": "bad", "mass": -1}))
    run(npx + ["export", "mujoco-test-box", bad, "-o", out], env, cwd=project, expect=2)
    now = {p.name: p.read_text() for p in out.iterdir()}
    if now != earlier:
        fail(f"npx flipcheck export of a good and a bad scenario changed {sorted(now)}")
    print("npx flipcheck export checks every scenario before it writes any")


def main(bookspin, source, build):
    for program in ("em++", "node", "npm"):
        if shutil.which(program) is None:
            missing(f"{program} not found")
    cannon = source / "web" / "node_modules" / "cannon-es"
    if not cannon.is_dir():
        missing("the npm package cannon-es (web/node_modules)")
    pinned = json.loads((source / "web" / "package-lock.json").read_text())["packages"][
        "node_modules/cannon-es"]["version"]
    installed = json.loads((cannon / "package.json").read_text())["version"]
    if installed != pinned:
        fail(f"web/node_modules has cannon-es {installed}, web/package-lock.json pins {pinned}")
    if subprocess.run(["node", source / "web" / "flipcheck-engines.mjs", "--check"],
                      capture_output=True).returncode != 0:
        missing("the league's npm packages (web/node_modules)")

    # Built by npm/build.sh before this test (Npm.PackageBuilds, the fixture of every test that
    # uses BUILD/npm/package), not here: the engines' runner may be reading it meanwhile.
    tgzs = sorted((build / "npm").glob("flipcheck-*.tgz"))
    if len(tgzs) != 1:
        fail(f"expected one BUILD/npm/flipcheck-*.tgz (make npm: npm/build.sh), found {tgzs}")
    tgz = tgzs[0]
    if tgz.stat().st_size >= 3e6:
        fail(f"{tgz.name} is {tgz.stat().st_size} bytes, over 3 MB")
    with tarfile.open(tgz) as tar:
        manifest = json.load(tar.extractfile("package/package.json"))
        names = tar.getnames()
    # One version (docs/flipcheck.md, "Versions"): VERSION's, in the file's name and package.json.
    version = re.search(r"^version (\S+)$", (source / "VERSION").read_text(), re.M).group(1)
    if manifest.get("version") != version or tgz.name != f"flipcheck-{version}.tgz":
        fail(f"{tgz.name}: package.json's version {manifest.get('version')!r}, VERSION says {version!r}")
    if manifest.get("dependencies"):
        fail(f"the package has runtime dependencies: {manifest['dependencies']}")
    for name in ("package/index.mjs", "package/index.d.ts", "package/cli.mjs",
                 "package/flipcheck-wasm.cjs"):
        if name not in names:
            fail(f"{tgz.name} lacks {name}")

    # The package's own JavaScript around the WebAssembly (tests/npm/index_test.mjs).
    unit = run(["node", "--test", source / "tests" / "npm" / "index_test.mjs"],
               {**os.environ, "FLIPCHECK_PACKAGE": str(build / "npm" / "package")})
    if "# fail 0" not in unit.stdout or "# pass 0" in unit.stdout:
        fail(f"tests/npm/index_test.mjs:\n{unit.stdout}")
    print("index.mjs under node --test: " + unit.stdout.split("# pass ")[1].split()[0] + " tests pass")

    with tempfile.TemporaryDirectory(prefix="flipcheck-npm-") as tmp:
        tmp = pathlib.Path(tmp)
        proxy = "http://127.0.0.1:9"  # the discard port: a download would fail
        env = {k: v for k, v in os.environ.items()
               if not k.lower().startswith("npm_config_") and not k.lower().endswith("_proxy")}
        env.update(HOME=str(tmp / "home"), npm_config_cache=str(tmp / "npm-cache"),
                   npm_config_offline="true", npm_config_audit="false", npm_config_fund="false",
                   npm_config_update_notifier="false", http_proxy=proxy, https_proxy=proxy,
                   HTTP_PROXY=proxy, HTTPS_PROXY=proxy)
        project = tmp / "my-engine"
        shutil.copytree(source / "examples" / "flipcheck-npm", project)
        run(["npm", "pack", "--ignore-scripts", "--silent", "--pack-destination", tmp, cannon], env)
        run(["npm", "install", "--ignore-scripts", tmp / f"cannon-es-{pinned}.tgz", tgz], env,
            cwd=project)

        # The example, as its package.json's test script runs it.
        tested = run(["npm", "test"], env, cwd=project)
        if "# pass 7" not in tested.stdout or "# fail 0" not in tested.stdout:
            fail(f"examples/flipcheck-npm: expected 7 passing tests:\n{tested.stdout}")
        print("examples/flipcheck-npm: 7 tests pass under node --test")

        # cannon-es' motions, judged by the package and by the command line.
        motions = tmp / "motions"
        motions.mkdir()
        shutil.copy(source / "tests" / "npm" / "cannon_motions.mjs", project)
        run(["node", "cannon_motions.mjs", motions], env, cwd=project)
        result = json.loads((motions / "judgements.json").read_text())
        scenarios = sorted(p.stem for p in (source / "scenes" / "flipcheck").glob("*.toml"))
        if sorted(result["judged"]) != scenarios:
            fail(f"the package's scenarios {sorted(result['judged'])} are not {scenarios}")
        npx = [project / "node_modules" / ".bin" / "flipcheck"]
        said = run(npx + ["--version"], env, cwd=project).stdout
        if said != f"flipcheck {version}\n":
            fail(f"npx flipcheck --version printed {said!r}, VERSION says {version}")
        for name in scenarios:
            judged = result["judged"][name]
            file = motions / judged["file"]
            scene = source / "scenes" / "flipcheck" / f"{name}.toml"
            cli = run([bookspin, "flipcheck", "judge", scene, file, "-o", tmp / "cli"], expect=3)
            row = read_csv((tmp / "cli" / f"{name}-judge.csv").read_text())[0]
            same_row(row, judged["arrays"], f"{name}: judge()")
            same_row(row, judged["csv"], f"{name}: judgeCsv()")
            # The judgement records the version and the SHA-256 of the scenario JSON the package
            # carries, byte for byte the command line's export.
            carried = project / "node_modules" / "flipcheck" / "scenarios" / f"{name}.json"
            if (row["version"], row["scenario_sha256"]) != (
                    version, hashlib.sha256(carried.read_bytes()).hexdigest()):
                fail(f"{name}: the judgement records {row['version']} {row['scenario_sha256']}, "
                     f"VERSION says {version}, the carried scenario hashes to "
                     f"{hashlib.sha256(carried.read_bytes()).hexdigest()}")
            if judged["arrays"]["pass"] != (row["verdict"] == "pass"):
                fail(f"{name}: pass is {judged['arrays']['pass']}, the verdict {row['verdict']}")
            ours = run(npx + ["judge", name, file, "-o", tmp / "npx"], env, cwd=project, expect=3)
            want = cli.stdout.replace(str(tmp / "cli"), str(tmp / "npx"))
            if len(ours.stdout.splitlines()) != len(want.splitlines()) or not all(
                    same_line(a, b) for a, b in zip(ours.stdout.splitlines(), want.splitlines())):
                fail(f"{name}: npx flipcheck judge printed\n{ours.stdout}the command line\n{want}")
            got = read_csv((tmp / "npx" / f"{name}-judge.csv").read_text())[0]
            same_row(row, {k: (None if v == "" else v) for k, v in got.items()}, f"{name}: npx CSV")
            print(f"{name}: cannon-es {row['verdict']} ({row['failures']}): the package as the "
                  "command line")

        # Every JavaScript engine the league runs (web/flipcheck-engines.mjs, from
        # web/node_modules), in the three shorter scenarios: npx flipcheck judge of their
        # motion files as the command line's judge of the same files.
        league = ("mujoco-test-box", "book-intermediate-0.2", "symmetric-top")
        exported = tmp / "league-export"
        run([bookspin, "flipcheck", "export",
             *[source / "scenes" / "flipcheck" / f"{n}.toml" for n in league], "-o", exported])
        engines = tmp / "league-motions"
        run(["node", source / "web" / "flipcheck-engines.mjs", "--flipcheck",
             build / "npm" / "package", engines, *[exported / f"{n}.json" for n in league]])
        for name in league:
            files = sorted(engines.glob(f"{name}-*.csv"))
            if len(files) < 11:
                fail(f"{name}: the league's runner wrote {len(files)} motions, expected 11")
            scene = source / "scenes" / "flipcheck" / f"{name}.toml"
            # cannon-es among them fails: exit 3 in both doors.
            cli = run([bookspin, "flipcheck", "judge", scene, *files, "-o", tmp / "league-cli"],
                      expect=3)
            ours = run(npx + ["judge", name, *files, "-o", tmp / "league-npx"], env, cwd=project,
                       expect=3)
            want = cli.stdout.replace(str(tmp / "league-cli"), str(tmp / "league-npx"))
            if len(ours.stdout.splitlines()) != len(want.splitlines()) or not all(
                    same_line(a, b) for a, b in zip(ours.stdout.splitlines(), want.splitlines())):
                fail(f"{name}: npx flipcheck judge printed\n{ours.stdout}the command line\n{want}")
            rows = read_csv((tmp / "league-cli" / f"{name}-judge.csv").read_text())
            got = read_csv((tmp / "league-npx" / f"{name}-judge.csv").read_text())
            if [r["motion"] for r in rows] != [r["motion"] for r in got]:
                fail(f"{name}: npx judged {[r['motion'] for r in got]}")
            for a, b in zip(rows, got):
                same_row(a, {k: (None if v == "" else v) for k, v in b.items()},
                         f"{name}: {a['motion']}")
            verdicts = ", ".join(f"{r['motion'][len(name) + 1:-4]} {r['verdict']}" for r in rows)
            print(f"{name}: {len(rows)} engine modes judged by npx as by the command line ({verdicts})")

        # export: the scenario JSON byte for byte, the exact motion to 1e-12.
        run([bookspin, "flipcheck", "export", source / "scenes" / "flipcheck" / "mujoco-test-box.toml",
             "-o", tmp / "cli-export"])
        exported = run(npx + ["export", "mujoco-test-box", "-o", tmp / "npx-export"], env,
                       cwd=project)
        want = f"exported: {tmp}/npx-export/mujoco-test-box.json, {tmp}/npx-export/mujoco-test-box-exact.csv\n"
        if exported.stdout != want:
            fail(f"npx flipcheck export printed {exported.stdout!r}, expected {want!r}")
        a = (tmp / "cli-export" / "mujoco-test-box.json").read_text()
        b = (tmp / "npx-export" / "mujoco-test-box.json").read_text()
        if a != b:
            fail(f"npx flipcheck export's JSON differs:\n{a}\n{b}")
        rows_a = read_csv((tmp / "cli-export" / "mujoco-test-box-exact.csv").read_text())
        rows_b = read_csv((tmp / "npx-export" / "mujoco-test-box-exact.csv").read_text())
        if len(rows_a) != len(rows_b) or list(rows_a[0]) != list(rows_b[0]):
            fail("npx flipcheck export's exact CSV has other rows or columns")
        for i, (ra, rb) in enumerate(zip(rows_a, rows_b)):
            for column in ra:
                if not same_number(float(ra[column]), float(rb[column])):
                    fail(f"exact CSV row {i}: {column}: {ra[column]} against {rb[column]}")
        print("npx flipcheck export: the command line's files")

        # Bad input: the command line's one line.
        bad = motions / "nan.csv"
        bad.write_text("t,qw,qx,qy,qz,wx,wy,wz\n0,1,0,0,0,1,2,3\n0.01,1,0,0,0,nan,2,3\n")
        scene = source / "scenes" / "flipcheck" / "mujoco-test-box.toml"
        for path in (bad, motions / "missing.csv", motions):
            cli = run([bookspin, "flipcheck", "judge", scene, path, "-o", tmp / "cli"], expect=2)
            ours = run(npx + ["judge", "mujoco-test-box", path, "-o", tmp / "npx-bad"], env,
                       cwd=project, expect=2)
            a = error_line(cli.stderr, "bookspin: error: ")
            b = error_line(ours.stderr, "flipcheck: error: ")
            if a != b:
                fail(f"bad input {path.name}: the command line says {a!r}, npx {b!r}")
            if (tmp / "npx-bad").exists():
                fail("npx flipcheck judge wrote a file for bad input")
        api = result["errors"]["nan"]
        want = error_line(run([bookspin, "flipcheck", "judge", scene, bad, "-o", tmp / "cli"],
                              expect=2).stderr, "bookspin: error: ").replace(str(bad), "nan.csv")
        if api != want:
            fail(f"judgeCsv of a NaN threw {api!r}, the command line says {want!r}")
        if "omegaWorld" not in (result["errors"]["shape"] or ""):
            fail(f"judge of a wrong shape threw {result['errors']['shape']!r}")
        if "no scenario \"no-such-scenario\"" not in (result["errors"]["scenario"] or ""):
            fail(f"scenario() of an unknown name threw {result['errors']['scenario']!r}")
        run(npx + ["judge", "no-such-scenario", bad], env, cwd=project, expect=2)
        for key, said in (("bigint", "q: holds BigInts (BigInt64Array): expected numbers"),
                          ("nullScenario", "flipcheck: a scenario is a name or a scenario JSON "
                                           "object, got null")):
            if not (result["errors"][key] or "").startswith(said):
                fail(f"{key}: threw {result['errors'][key]!r}, expected {said!r}…")
        (motions / "null.json").write_text("null\n")
        said = error_line(run(npx + ["judge", motions / "null.json", bad], env, cwd=project,
                              expect=2).stderr, "flipcheck: error: ")
        if not said.startswith(f"{motions / 'null.json'}: holds JSON null, not a scenario"):
            fail(f"a scenario file of JSON null: npx said {said!r}")
        print("bad input: the command line's one line, exit 2")

        ci_example(npx, env, project, tmp, bookspin, source)
        round_trips(npx, env, project, tmp, bookspin, source)
        export_checks_every_scenario_first(npx, env, project, tmp)

        # A scenario JSON fuzzer (docs/flipcheck.md, "What a scenario may be"): the carried box
        # scenario with a field missing, mistyped, out of range or hostile, through npx export
        # and judge: exit 2 and one line naming the field, nothing written, and nothing ever
        # outside -o; the fields as written, unchanged, are judged.
        fuzz_scenarios(npx, env, project, tmp, source)
        scenario_refusals_at_every_door(npx, env, project, tmp, bookspin, build, source)

        # A seeded property of the judge through the package's judge() (tests/npm/judge_property.mjs).
        shutil.copy(source / "tests" / "npm" / "judge_property.mjs", project)
        prop = run(["node", "judge_property.mjs"], env, cwd=project)
        if not prop.stdout.rstrip().endswith("PASS"):
            fail(f"judge_property.mjs:\n{prop.stdout}{prop.stderr}")
        print(f"the judge's property at the npm door: {len(prop.stdout.splitlines()) - 1} random scenarios")
    print(f"PASS: {tgz.name} ({tgz.stat().st_size} bytes)")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve(),
         pathlib.Path(sys.argv[3]).resolve())
