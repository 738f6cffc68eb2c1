"""Unit tests of the top-level modules (workflow_config, io, cli, limits, formatting, inline_math) with tiny
inputs in tmp_path: a configuration refused key by key, a Results folder written, read back and refused once
tampered, stale results, the command line's one-line refusals, a child process stopped at its limits."""

import hashlib
import json
import math
from io import BytesIO

import pandas as pd
import pytest
import yaml

from classical_dynamics import cli, formatting, inline_math, io, limits
from classical_dynamics.results import Results
from classical_dynamics.workflow_config import ConfigError, check_config

# ---- workflow_config.py


def config_file(tmp_path, data):
    path = tmp_path / "config.yaml"
    path.write_text(yaml.safe_dump(data))
    return path


def test_a_good_configuration_gives_its_flags_with_defaults(tmp_path):
    path = config_file(tmp_path, {"quick": 1, "budget": {"seconds": 900, "memory_mb": 6000}})
    assert check_config({"quick": 1, "budget": {"seconds": 900, "memory_mb": 6000}}, path) == {
        "quick": True,
        "jobserver": True,
    }
    assert check_config({"jobserver": False, "archive": "dist/x.tar.gz"}, tmp_path / "none.yaml") == {
        "quick": False,
        "jobserver": False,
    }


@pytest.mark.parametrize(
    "config,filed,words",
    [
        ({"quik": 1}, False, "config 'quik': expected one of the keys quick"),
        ({"quick": 2}, True, "config 'quick': expected 0 or 1, got 2"),
        ({"jobserver": "yes"}, False, "expected 0 or 1"),
        ({"archive": "  "}, False, "the path of a dist archive"),
        ({"budget": 900}, True, "a mapping such as"),
        ({"budget": {"minutes": 15}}, True, "config 'budget.minutes': expected one of seconds, memory_mb"),
        ({"budget": {"seconds": -1}}, False, "config 'budget.seconds': expected a positive number"),
        ({"budget": {"memory_mb": math.inf}}, False, "a positive number"),
        ({"budget": {"seconds": True}}, False, "a positive number"),
    ],
)
def test_a_bad_configuration_value_is_one_line_naming_key_value_and_origin(tmp_path, config, filed, words):
    path = config_file(tmp_path, config if filed else {})
    with pytest.raises(ConfigError) as error:
        check_config(config, path)
    line = str(error.value)
    assert words in line and "\n" not in line
    assert line.startswith(path.as_posix() if filed else "the command line (--config)")


def test_a_configuration_file_that_is_not_yaml_is_refused(tmp_path):
    path = tmp_path / "config.yaml"
    path.write_text("quick: [1,\n")
    with pytest.raises(ConfigError, match="not YAML"):
        check_config({}, path)
    path.write_text("- a list\n")  # YAML, but no mapping: nothing of it counts as filed
    with pytest.raises(ConfigError, match="the command line"):
        check_config({"quick": 5}, path)


# ---- io.py: a tiny Results written, read back, refused when tampered, stale when its scene changed


def write_tiny(tmp_path, scene_bytes=b"title: t\n", quick=True):
    r = Results("chains", "toy", "t")
    r.number("x", 0.1, "1")
    r.table(
        "rows", pd.DataFrame({"a": [1, 2], "b": [0.5, float("nan")]}), "Rows.", headers={"a": "a", "b": "b"}
    )
    folder = tmp_path / "results" / "chains" / "toy"
    r.write(
        folder,
        tmp_path / "results" / "chains" / "timings" / "toy",
        {"scene_sha256": hashlib.sha256(scene_bytes).hexdigest(), "quick": quick},
        {"wall_seconds": 0.0},
    )
    return folder


def test_a_written_folder_reads_back_and_its_provenance_hashes_every_file(tmp_path):
    folder = write_tiny(tmp_path)
    provenance = io.check_result_folder(folder)
    for name, digest in provenance["files"].items():  # sha256 of the bytes on disk, computed here
        assert hashlib.sha256((folder / name).read_bytes()).hexdigest() == digest
    summary = io.read_json_checked(folder / "summary.json")
    assert summary["numbers"]["x"] == {"value": 0.1, "unit": "1"}
    assert (folder / "rows.csv").read_text().splitlines()[0] == "a,b"
    assert io.result_folders(tmp_path / "results" / "chains") == [folder]


@pytest.mark.parametrize(
    "damage,words",
    [
        (lambda f: (f / "rows.csv").write_text("a,b\n1,9\n"), "rows.csv: does not match its checksum"),
        (lambda f: (f / "rows.csv").unlink(), "rows.csv: missing"),
        (lambda f: (f / "provenance.json").write_text("{"), "unreadable or not JSON"),
        (lambda f: (f / "provenance.json").write_text('{"files": {}}'), "lists no file checksums"),
        (
            lambda f: (f / "provenance.json").write_text('{"files": {"summary.json": "0", "../x": "0"}}'),
            "not a file of its folder",
        ),
    ],
)
def test_a_tampered_folder_is_refused_naming_the_file(tmp_path, damage, words):
    folder = write_tiny(tmp_path)
    damage(folder)
    with pytest.raises(io.ResultError, match=words):
        io.check_result_folder(folder)
    assert words.split(":")[0] in io.stale_reason(folder, tmp_path / "scene.yaml", True)


def test_results_are_stale_when_their_scene_or_build_mode_changed(tmp_path):
    folder = write_tiny(tmp_path, b"title: t\n", quick=True)
    scene = tmp_path / "scene.yaml"
    scene.write_bytes(b"title: t\n")
    assert io.stale_reason(folder, scene, True) is None
    assert "a full build is asked for" in io.stale_reason(folder, scene, False)
    scene.write_bytes(b"title: u\n")
    assert "built from other bytes" in io.stale_reason(folder, scene, True)
    assert io.stale_reason(folder, tmp_path / "gone.yaml", True) is None


def test_checked_json_refuses_what_python_would_accept(tmp_path):
    assert io.loads_checked(b'{"a": [1, 2.5]}') == {"a": [1, 2.5]}
    for bad in (b'{"a": NaN}', b'{"a": 1e999}', b'{"a": Infinity}', b"[" * 100 + b"]" * 100, b"9" * 400):
        with pytest.raises(ValueError):
            io.loads_checked(bad)
    assert json.loads(io.dumps_json({"n": float("nan"), "i": 3})) == {"n": None, "i": 3}
    path = tmp_path / "big.bin"
    path.write_bytes(b"x" * 100)
    assert io.sha256_bounded(path) == hashlib.sha256(b"x" * 100).hexdigest()
    with pytest.raises(ValueError):
        io.regular_size(path, 10)
    with pytest.raises(ValueError):
        io.sha256_bounded(path, 10)


def test_a_full_disk_is_one_line_naming_the_file():
    import errno

    line = io.no_space_line(OSError(errno.ENOSPC, "No space left on device", "results/x.csv"))
    assert line.startswith("results/x.csv: no space left on device") and "\n" not in line
    assert io.no_space_line(OSError(errno.EACCES, "denied", "x")) is None
    assert io.no_space_line(ValueError("x")) is None


# ---- cli.py: one line for a user's mistake


def test_validate_accepts_a_good_scene_and_refuses_a_bad_one_in_one_line(tmp_path, capsys):
    good = tmp_path / "inertia.yaml"
    good.write_text(yaml.safe_dump({"title": "Moments", "problem": "inertia", "numerics": {"nodes": 8}}))
    assert cli.main(["validate", "solvers", str(good)]) == 0
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump({"title": "Moments", "problem": "inertia", "numerics": {"nodes": "many"}}))
    assert cli.main(["validate", "solvers", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert "bad.yaml" in err and "numerics.nodes" in err and "\n" not in err


def test_the_guard_turns_a_full_disk_and_exhausted_memory_into_one_line(capsys):
    import errno
    from types import SimpleNamespace

    def full(_):
        raise OSError(errno.ENOSPC, "No space left on device", "results/x.csv")

    def hungry(_):
        raise MemoryError

    def other(_):
        raise OSError(errno.EACCES, "denied")

    args = SimpleNamespace(command="run", scene="solvers/inertia")
    assert cli._guarded(full, args) == 2
    assert cli._guarded(hungry, args) == 3
    err = capsys.readouterr().err.splitlines()
    assert err[0].startswith("results/x.csv: no space left") and err[1].startswith("solvers/inertia: stopped")
    with pytest.raises(OSError):
        cli._guarded(other, args)


def test_dist_refuses_a_tampered_results_folder(tmp_path, capsys):
    folder = write_tiny(tmp_path)
    (folder / "rows.csv").write_text("edited\n")
    assert cli.main(["dist", str(tmp_path / "results"), str(tmp_path / "d.tar.gz")]) == 2
    assert "rows.csv" in capsys.readouterr().err and not (tmp_path / "d.tar.gz").exists()


# ---- limits.py: a child process stopped at its limits


def test_a_child_returns_its_status_and_is_stopped_past_its_memory_limit(capsys):
    assert limits.run_limited(lambda: 0, "ok", 60, 10_000) == 0
    assert limits.run_limited(lambda: 5, "five", 60, 10_000) == 5

    def leave():
        raise SystemExit(4)

    assert limits.run_limited(leave, "leave", 60, 10_000) == 4

    def hungry():
        import time

        block = bytearray(300 << 20)  # 300 MB, touched
        for i in range(0, len(block), 4096):
            block[i] = 1
        time.sleep(30)
        return 0

    assert limits.run_limited(hungry, "solvers/big", 60, 100) == 3
    assert "solvers/big: stopped: it used" in capsys.readouterr().err
    assert limits.rule_resources({"max_rss_mb": 120, "seconds": 30}) == {"mem_mb": 500, "runtime": 5}
    assert limits.resident_mb(2**22 + 12345) == 0.0  # no such process


# ---- formatting.py and inline_math.py


def test_formatting_rounds_first_then_chooses_the_notation():
    x = "\u202f×\u202f"  # a narrow no-break space either side of the times sign
    # rounded first: 99 999.6 at five figures is 1.0000 × 10⁵, 9.9996 at four is 10.00
    assert formatting.format_number(99999.6, 5) == f"1.0000{x}10⁵"
    assert formatting.format_number(9.9996, 4) == "10.00"
    assert formatting.format_number(0.000123456, 3) == f"1.23{x}10⁻⁴"
    assert formatting.format_number(-12345678, 4) == "−12\u202f345\u202f678"  # a count prints exactly
    assert [formatting.format_number(v) for v in (None, True, "text", float("nan"), -math.inf, 0.0)] == [
        "—",
        "yes",
        "text",
        "NaN",
        "−∞",
        "0",
    ]
    # a column in one notation once any value needs a power of ten; decimals down to 10⁻⁴; no figures a value
    # does not have; counts exactly
    assert formatting.format_column([1.0, 1e-6, None, 0.0]) == ["1", f"1{x}10⁻⁶", "—", "0"]  # no × 10⁰
    assert formatting.format_column([2.22, 3.1e-16, 45.9]) == ["2.22", f"3.10{x}10⁻¹⁶", f"4.59{x}10¹"]
    assert formatting.format_column([1.0, 0.0001, None, 0.0]) == ["1", "0.0001", "—", "0"]
    assert formatting.format_column([9.22649, 0.000217893]) == ["9.226", "0.0002179"]
    assert formatting.format_column([1, 2.5]) == ["1", "2.5"]
    assert formatting.format_column([16.0, 262144.0, float("nan")]) == ["16", "262\u202f144", "NaN"]
    # a hard case's measured value and bound in one notation, the bound to its own figures
    assert formatting.measured_and_bound(0.7312, 1.0) == ("0.73", "1")
    assert formatting.measured_and_bound(2.31e-12, 1e-9) == (f"2.3{x}10⁻¹²", f"1{x}10⁻⁹")
    assert formatting.measured_and_bound(0.0, 2.5e-6) == ("0", f"2.5{x}10⁻⁶")
    assert formatting.measured_and_bound(0.5, 1e-6) == (f"5.0{x}10⁻¹", f"1{x}10⁻⁶")
    assert [formatting.exact_figures(v) for v in (0.5, 100.0, 2.0**-0.5, 0.125)] == [1, 1, 16, 3]
    assert (
        formatting.format_decimals(-0.0004, 2) == "0" and formatting.format_decimals(-3.14159, 2) == "−3.14"
    )
    assert formatting.shortest(50.5) == "50.5" and formatting.shortest(1e-10) == f"1{x}10⁻¹⁰"
    assert formatting.shortest(306.0) == "306" and formatting.shortest(None) == "—"
    assert formatting.plural(1, "run") == "run" and formatting.plural(1.5, "year") == "years"
    assert formatting.plural(3, "body", "bodies") == "bodies"
    # 1 % supports 3 figures; an absolute 0.5 on 100 the digits down to the units: 3
    assert formatting.sig_for_tolerance(1.0, relative=0.01) == 3
    assert formatting.sig_for_tolerance(100.0, absolute=0.5) == 4
    assert formatting.sig_for_tolerance(1.0) == 4
    assert formatting.needs_power_of_ten(1e-7) and not formatting.needs_power_of_ten(math.inf)


def test_inline_math_typesets_and_flattens():
    html = inline_math.render_text("the period $T = 2\\pi/\\omega$ in s")
    assert html == "the period <span class=math><i>T</i> = 2<i>π</i>/<i>ω</i></span> in s"
    assert "$" not in inline_math.plain_text("$\\omega_0^2$")
    # an operator name stands apart from its argument as \sin does (arcsinh m₁, not arcsinhm₁)
    assert inline_math.render_text("$\\operatorname{arcsinh}m_1$") == (
        "<span class=math><span class=fn>arcsinh</span>\u2009<i>m</i><sub>1</sub></span>"
    )
    assert "</span>(" in inline_math.render_text("$\\operatorname{arcoth}(x)$")


def test_prose_quotes_turn_and_references_hold_together():
    html = inline_math.render_text('about $e$ "with angular velocity $\\Omega$" $= 1$ (Ex. XI.1, Arts. 96)')
    assert "“with angular velocity" in html and "</span>” " in html and '"' not in html
    assert "<span class=nw>Ex.\u00a0XI.1</span>" in html and "<span class=nw>Arts.\u00a096</span>" in html


def test_plain_text_keeps_scripts_readable():
    # a CSV or an alt text reads ω₃², not ω32; a script with no Unicode form is marked, a radicand bracketed
    flat = inline_math.plain_text(
        "$\\omega_3^2$, $e^{-\\nu t}$, $\\sqrt{g/a}$, $\\Omega_\\mathrm{b}$, $10^{-6}$"
    )
    assert flat == "ω₃², e^(−ν t), √(g/a), Ω_b, 10⁻⁶"


# ---- verify.py in-process: diff of two tiny builds, an archive checked whole and refused once tampered


def write_build(base, value, extra_scene=False):
    results = base / "results"
    for scene, x in (("toy", value), ("more", 1.0)) if extra_scene else (("toy", value),):
        r = Results("chains", scene, "t")
        r.number("x", x, "1")
        r.number("n", 3, "1")
        r.hard_case("small", "a small error", 1e-12, 1e-10)
        folder = results / "chains" / scene
        r.write(folder, results / "chains" / "timings" / scene, {"commit": "abc"}, {"wall_seconds": 0.0})
    return results


def test_diff_names_each_changed_number_and_each_scene_present_on_one_side(tmp_path):
    import io as stdio

    from classical_dynamics import verify

    a, b = write_build(tmp_path / "a", 0.1), write_build(tmp_path / "b", 0.1 * (1 + 1e-6), extra_scene=True)
    out = stdio.StringIO()
    assert verify.diff(a, b, out) == 1
    lines = out.getvalue().splitlines()
    assert lines[0].split() == ["study/scene", "number", "A", "B", "relative", "change"]
    assert any(line.split()[:2] == ["chains/more", "(whole"] and "added" in line for line in lines)
    (row,) = [line.split() for line in lines if line.startswith("chains/toy")]
    assert row[1] == "x" and float(row[4]) == pytest.approx(1e-6, rel=1e-6)  # (B - A)/|A|, by hand
    assert lines[-1].startswith("changed: 2 numbers in 2 scenes")
    out = stdio.StringIO()
    assert verify.diff(a, a, out) == 0 and out.getvalue().startswith(
        "no numbers changed (3 numbers in 1 scenes)"
    )
    with pytest.raises(verify.VerifyError, match="not a results folder"):
        verify.diff(tmp_path, a)


def retar(archive, target, change):
    """A copy of `archive` with one member's bytes changed by change(name, data)."""
    import tarfile

    with tarfile.open(archive) as source, tarfile.open(target, "w:gz") as out:
        for member in source.getmembers():
            data = source.extractfile(member).read()
            data = change(member.name, data)
            member.size = len(data)
            out.addfile(member, BytesIO(data))


def test_an_archive_is_checked_whole_and_refused_once_a_member_is_tampered(tmp_path):
    from classical_dynamics import verify
    from classical_dynamics.report.dist import make_archive

    results = write_build(tmp_path, 0.25)
    archive = tmp_path / "dist" / "classical-dynamics-0.0.0-results.tar.gz"
    make_archive(results, archive, with_report=False)
    unpacked = verify.unpack_archive(archive, tmp_path / "unpacked")
    assert verify.scenes_of(unpacked) == [("chains", "toy")]
    numbers = verify.read_numbers(unpacked)
    assert (
        numbers["chains", "toy", "x"]["value"] == 0.25
        and numbers["chains", "toy", "hard_case:small"]["value"]
    )
    assert (
        verify.open_results(unpacked, tmp_path / "unused") == unpacked
    )  # an unpacked archive, checked again
    # the same archive with one byte of a summary changed: its SHA256SUMS no longer matches
    bad = tmp_path / "bad" / archive.name
    bad.parent.mkdir()
    retar(
        archive,
        bad,
        lambda name, data: data.replace(b"0.25", b"0.26") if name.endswith("summary.json") else data,
    )
    with pytest.raises(verify.VerifyError, match="checksum mismatch for .*summary.json"):
        verify.unpack_archive(bad, tmp_path / "bad_unpacked")
    # a member SHA256SUMS does not list
    retar(
        archive,
        bad,
        lambda name, data: data + b"0" * 64 + b"  extra\n" if name.endswith("/SHA256SUMS") else data,
    )
    with pytest.raises(verify.VerifyError, match="extra is listed in SHA256SUMS but missing"):
        verify.unpack_archive(bad, tmp_path / "bad_unpacked2")
    (tmp_path / "garbage.tar.gz").write_bytes(b"not gzip at all")
    for given, words in (
        (tmp_path / "garbage.tar.gz", "not a readable tar.gz"),
        (tmp_path / "nothing.tar.gz", "no such file"),
        (tmp_path, "a folder, not a dist archive"),
    ):
        with pytest.raises(verify.VerifyError, match=words):
            verify.unpack_archive(given, tmp_path / "x")
    # the sum written beside the archive: a changed archive no longer matches it
    copy = tmp_path / "dist2" / archive.name
    copy.parent.mkdir()
    retar(archive, copy, lambda name, data: data)  # the same members, other gzip bytes
    (copy.parent / "SHA256SUMS").write_text(
        (archive.parent / "classical-dynamics-0.0.0-results.SHA256SUMS").read_text()
    )
    with pytest.raises(verify.VerifyError, match="checksum mismatch with"):
        verify.unpack_archive(copy, tmp_path / "copy_unpacked")


def test_a_tolerance_must_be_a_number_or_one_kind_and_value():
    from classical_dynamics import verify

    assert verify.parse_tolerance({"tolerance": {"relative": 0.1}}, "w") == ("relative", 0.1)
    assert verify.parse_tolerance({}, "w") is None
    for bad in (-1, {"relative": -1}, {"fuzzy": 1}, "1", {"relative": 1, "absolute": 1}):
        with pytest.raises(verify.VerifyError, match="w: tolerance"):
            verify.parse_tolerance({"tolerance": bad}, "w")
    change = verify.Change("s/c", "x", 2.0, 1.0)
    assert change.relative == -0.5 and verify.Change("s/c", "x", 0.0, 1.0).relative == math.inf
    assert verify.Change("s/c", "x", "a", 1.0).relative is None


@pytest.mark.parametrize(
    "source,html",
    [
        # what TeX prints, written out by hand: letters italic, \text and \mathrm upright, − for -
        (r"\text{a b}", "a b"),
        (r"\text x", "x"),  # TeX skips the space before an argument
        (r"\text{a{b}c}", "a{b}c"),
        (r"\mathrm{d}t", "d<i>t</i>"),
        (r"\frac12", "½"),
        (r"\frac {1}{4}", "¼"),
        (r"\frac{a+b}{c}", "(<i>a</i>+<i>b</i>)/<i>c</i>"),
        (r"\tfrac{x}{y}", "<i>x</i>/<i>y</i>"),
        (r"\sqrt{x}", "√<span class=radicand><i>x</i></span>"),
        (r"\dot{x}", "<i>x\u0307</i>"),
        (r"\mathbf{m}", "<b><i>m</i></b>"),
        (r"\sin x", "<span class=fn>sin</span>\u2009<i>x</i>"),
        (r"\sin(x)", "<span class=fn>sin</span>(<i>x</i>)"),
        (r"a'", "<i>a</i>′"),
        (r"-x", "−<i>x</i>"),
        (r"x^{2}_1", "<i>x</i><sub>1</sub><sup>2</sup>"),
        (r"x_ {i}", "<i>x</i><sub><i>i</i></sub>"),
        (r"\left( x \right)", "( <i>x</i> )"),
        (r"\Omega \epsilon \infty", "Ω <i>ϵ</i> ∞"),
    ],
)
def test_inline_math_is_typeset_as_tex_would(source, html):
    assert inline_math.math_html(source) == f"<span class=math>{html}</span>"


@pytest.mark.parametrize(
    "source,words",
    [
        ("x_", "ends early"),
        (r"\frac{1}", "ends early"),
        ("_x", "'_' with nothing before it"),
        ("{x", "missing '}'"),
        ("x}", "unbalanced '}'"),
        (r"\foo", r"unknown command \\foo"),
    ],
)
def test_malformed_inline_math_is_refused_naming_the_formula(source, words):
    with pytest.raises(inline_math.MathError, match=words):
        inline_math.math_html(source)
