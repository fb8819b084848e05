"""The JSON Schemas in docs/schema/ against what freestand writes.

Validates every shipped golden reports/<case>/result.json against result.schema.json, a
fragility.json the built CLI writes (FREESTAND_EXE) against fragility.schema.json, and checks
that broken documents fail. Runs under Debian's python3-pytest and python3-jsonschema (4.10) as
well as newer jsonschema (4.18+, which resolves references through `referencing`).
"""
import copy
import json
import os
import pathlib
import subprocess

import jsonschema
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCHEMA_DIR = ROOT / "docs" / "schema"
# reports/validation/result.json is the thesis validation (`freestand validate`), not an
# assessment: it has no schema of its own.
GOLDEN_RESULTS = sorted(p for p in (ROOT / "reports").glob("*/result.json") if p.parent.name != "validation")


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


SCHEMAS = {name: load(SCHEMA_DIR / f"{name}.schema.json") for name in ("result", "fragility")}


def validator(name):
    """A draft 2020-12 validator of the named schema that resolves the other schema's $refs."""
    schema = SCHEMAS[name]
    try:
        from referencing import Registry, Resource  # jsonschema >= 4.18
    except ImportError:
        store = {s["$id"]: s for s in SCHEMAS.values()}
        resolver = jsonschema.RefResolver.from_schema(schema, store=store)
        return jsonschema.Draft202012Validator(schema, resolver=resolver)
    registry = Registry().with_resources([(s["$id"], Resource.from_contents(s)) for s in SCHEMAS.values()])
    return jsonschema.Draft202012Validator(schema, registry=registry)


def errors(name, document):
    return [f"{'/'.join(map(str, e.absolute_path))}: {e.message}" for e in validator(name).iter_errors(document)]


@pytest.mark.parametrize("name", sorted(SCHEMAS))
def test_schema_is_a_valid_draft_2020_12_schema(name):
    jsonschema.Draft202012Validator.check_schema(SCHEMAS[name])


def test_there_are_goldens_of_both_kinds():
    kinds = {"pair" in load(p) for p in GOLDEN_RESULTS}
    assert kinds == {False, True}, "expected one-component and two-unit goldens in reports/"


@pytest.mark.parametrize("path", GOLDEN_RESULTS, ids=lambda p: p.parent.name)
def test_golden_result_json_follows_the_schema(path):
    assert errors("result", load(path)) == []


@pytest.fixture(scope="module")
def fragility_json(tmp_path_factory):
    """fragility.json of a small run of the built CLI on a shipped case (about 0.1 s): the El
    Centro pair of tests/data at 7 levels x 10 samples, where overturning has a fitted curve and
    sliding has none (no failure), so both forms of a fit are checked."""
    exe = os.environ.get("FREESTAND_EXE")
    if not exe:
        pytest.fail("FREESTAND_EXE is not set: run through ctest, or set it to the built freestand")
    out = tmp_path_factory.mktemp("fragility")
    records = [str(ROOT / "tests" / "data" / f"RSN175_IMPVALL.H_H-E{n}.AT2") for n in ("12140", "12230")]
    run = subprocess.run([exe, "fragility", str(ROOT / "cases" / "block-ts1.toml"), "--pga", "0.25:0.55:0.05",
                          "--samples", "10", "--records", *records, "--out", str(out)],
                         capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stderr
    document = load(out / "fragility.json")
    assert document["fit"]["overturn"] is not None and document["fit"]["slide"] is None
    return document


def test_fragility_json_follows_the_schema(fragility_json):
    assert errors("fragility", fragility_json) == []


def test_a_golden_result_carries_a_fragility_section():
    with_fragility = [p for p in GOLDEN_RESULTS if "fragility" in load(p)]
    assert with_fragility, "expected a golden result.json with a fragility section"


def broken_results():
    one = load(ROOT / "reports" / "glovebox-single" / "result.json")
    pair = load(ROOT / "reports" / "glovebox-pair-unbraced" / "result.json")
    cases = {}

    def case(label, doc, change):
        doc = copy.deepcopy(doc)
        change(doc)
        cases[label] = doc

    case("missing stamp", one, lambda d: d.pop("stamp"))
    case("unknown top-level key", one, lambda d: d.update(extra=1))
    case("unknown key in a level", one, lambda d: d["levels"][0].update(slide_mm=3.0))
    case("string where a number belongs", one, lambda d: d["levels"][0].update(pga_g="0.3"))
    case("unknown verdict kind", one, lambda d: d["overall"].update(kind="fine"))
    case("bad commit", one, lambda d: d["stamp"].update(commit="HEAD"))
    case("a unit missing from a pair", pair, lambda d: d["units"].pop())
    case("a pair unit with a stamp", pair, lambda d: d["units"][0].update(stamp=d["stamp"]))
    return cases


@pytest.mark.parametrize("label,document", sorted(broken_results().items()))
def test_a_broken_result_fails(label, document):
    assert errors("result", document), f"{label}: expected a schema error"


def test_a_broken_fragility_json_fails(fragility_json):
    for label, change in {
        "missing levels": lambda d: d.pop("levels"),
        "negative count": lambda d: d["levels"][0]["events"]["any"].update(k=-1),
        "unknown event": lambda d: d["fit"].update(collapse=None),
        "interval of three": lambda d: d["levels"][0]["events"]["slide"].update(ci=[0, 0.5, 1]),
    }.items():
        doc = copy.deepcopy(fragility_json)
        change(doc)
        assert errors("fragility", doc), f"{label}: expected a schema error"
