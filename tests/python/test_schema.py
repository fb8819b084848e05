"""The JSON Schemas in docs/schema/ against what freestand writes.

Validates the result.json the built CLI (FREESTAND_EXE) writes for shipped cases of every kind
against result.schema.json, a fragility.json it writes against fragility.schema.json, and
checks that broken documents fail. Runs under Debian's python3-pytest and python3-jsonschema (4.10) as
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
# Shipped cases at one level each, which between them write every kind of result.json: one
# component, with a fragility section (block-ts3), with a performance goal (steel pads), and two
# units joined by a tunnel (simulated at 0.1 g).
FRESH_CASES = {"block-ts1": "0.3", "block-ts3": "0.3", "glovebox-steel-pads": "0.3",
               "glovebox-pair-unbraced": "0.1"}


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


def freestand_exe():
    exe = os.environ.get("FREESTAND_EXE")
    if not exe:
        pytest.fail("FREESTAND_EXE is not set: run through ctest, or set it to the built freestand")
    return exe


@pytest.fixture(scope="module")
def fresh_results(tmp_path_factory):
    """result.json of each of FRESH_CASES, written by this run of the built CLI."""
    out = tmp_path_factory.mktemp("assess")
    documents = {}
    for name, pga in FRESH_CASES.items():
        run = subprocess.run([freestand_exe(), "assess", str(ROOT / "cases" / f"{name}.toml"),
                              "--pga", pga, "--threads", "2", "--out", str(out / name)],
                             capture_output=True, text=True, check=False)
        assert run.returncode == 0, run.stderr
        documents[name] = load(out / name / "result.json")
    return documents


def test_fresh_results_are_of_every_kind(fresh_results):
    docs = fresh_results.values()
    assert {"pair" in d for d in docs} == {False, True}, "expected one-component and two-unit results"
    assert any("fragility" in d for d in docs), "expected a result with a fragility section"
    assert any("performance_goal" in d for d in docs), "expected a result with a performance goal"


@pytest.mark.parametrize("name", sorted(FRESH_CASES))
def test_fresh_result_json_follows_the_schema(fresh_results, name):
    assert errors("result", fresh_results[name]) == []


@pytest.fixture(scope="module")
def fragility_json(tmp_path_factory):
    """fragility.json of a small run of the built CLI on a shipped case (about 0.1 s): the El
    Centro pair of tests/data at 7 levels x 10 samples, where overturning has a fitted curve and
    sliding has none (no failure), so both forms of a fit are checked."""
    exe = freestand_exe()
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


# A change that breaks a document, applied to one component's result (steel pads) or a pair's.
BROKEN_RESULTS = {
    "missing stamp": ("glovebox-steel-pads", lambda d: d.pop("stamp")),
    "unknown top-level key": ("glovebox-steel-pads", lambda d: d.update(extra=1)),
    "unknown key in a level": ("glovebox-steel-pads", lambda d: d["levels"][0].update(slide_mm=3.0)),
    "string where a number belongs": ("glovebox-steel-pads",
                                      lambda d: d["levels"][0].update(pga_g="0.3")),
    "unknown verdict kind": ("glovebox-steel-pads", lambda d: d["overall"].update(kind="fine")),
    "bad commit": ("glovebox-steel-pads", lambda d: d["stamp"].update(commit="HEAD")),
    "a unit missing from a pair": ("glovebox-pair-unbraced", lambda d: d["units"].pop()),
    "a pair unit with a stamp": ("glovebox-pair-unbraced",
                                 lambda d: d["units"][0].update(stamp=d["stamp"])),
}


@pytest.mark.parametrize("label", sorted(BROKEN_RESULTS))
def test_a_broken_result_fails(fresh_results, label):
    name, change = BROKEN_RESULTS[label]
    document = copy.deepcopy(fresh_results[name])
    assert errors("result", document) == [], f"{label}: the unbroken document must pass"
    change(document)
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
