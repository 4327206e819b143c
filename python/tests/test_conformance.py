"""The Python package as an implementation of the conformance protocol: the adapter of
python/examples/conformance_adapter.py (the one spec/conformance.md shows) passes the
harness's cases, with --exact too, and refuses every invalid input."""

import json
import sys

from conftest import ROOT

ADAPTER = ROOT / "python" / "examples" / "conformance_adapter.py"
SELECTION = ["reduce/generated/*", "quad/quad-generated/*/lrs-s0", "quad/quad-generated/*/ds-s1",
             "simplify/*/run0", "simplify/*/run7", "decimate/*/run[0369]", "invalid/*"]


def test_the_python_adapter_passes_the_suite_exactly(cli):
    runs = [arg for glob in SELECTION for arg in ("--run", glob)]
    r = cli("--json", "conformance", "--suite", ROOT / "spec", "--exact", "-j", "2",
            "--impl", f"{sys.executable} {ADAPTER}", *runs, check=False)
    report = json.loads(r.stdout)
    assert r.returncode == 0, [c for c in report["cases"] if c["verdict"] != "passed"][:3]
    totals = {(t["task"], t["class"]): t for t in report["totals"]}
    assert set(totals) == {(task, cls) for task in ("reduce", "quad", "simplify", "decimate")
                           for cls in ("valid", "invalid")}
    assert all(t["failed"] == 0 and t["timed_out"] == 0 for t in totals.values())
    assert all(t["refused"] == t["passed"] > 0 for (_, cls), t in totals.items() if cls == "invalid")
    assert sum(t["passed"] for t in totals.values()) == len(report["cases"]) == 148


def test_the_specification_shows_the_tested_adapter():
    spec = (ROOT / "spec" / "conformance.md").read_text(encoding="utf-8")
    code = ADAPTER.read_text(encoding="utf-8")
    assert code in spec, "spec/conformance.md must show python/examples/conformance_adapter.py verbatim"
    assert len(code.splitlines()) <= 30


def _schemas():
    import jsonschema

    load = lambda name: json.loads((ROOT / "spec" / "protocol" / name).read_text(encoding="utf-8"))
    case, answer = load("case-v1.schema.json"), load("answer-v1.schema.json")
    for s in (case, answer):
        jsonschema.Draft202012Validator.check_schema(s)
    return jsonschema.Draft202012Validator(case), jsonschema.Draft202012Validator(answer)


def _answer(message):
    import subprocess

    from conftest import cli_binary
    r = subprocess.run([str(cli_binary()), "answer"], input=json.dumps(message),
                       capture_output=True, text=True)
    return r.returncode, json.loads(r.stdout)


def test_messages_follow_the_published_schemas():
    case_schema, answer_schema = _schemas()
    lines = []
    for name in ("invalid.jsonl", "wrong-answers.jsonl"):
        lines += [json.loads(l) for l in (ROOT / "spec" / "suite" / name).read_text().splitlines()]
    keys = ("id", "task", "options", "vertex_count", "faces", "positions")
    for line in lines:
        message = {"protocol": 1, **{k: line[k] for k in keys}}
        case_schema.validate(message)
        code, answer = _answer(message)
        answer_schema.validate(answer)
        # Our adapter refuses the invalid inputs (exit 2) and answers the others.
        assert (code == 2) == (line["class"] == "invalid"), line["id"]
        if "answer" in line:
            answer_schema.validate(line["answer"])
    # The schemas are not vacuous: a message missing its faces, an answer with both an
    # output and an error, and a quad of five corners are refused.
    bad_case = {"protocol": 1, "id": "x", "task": "reduce", "options": {}, "vertex_count": 3,
                "positions": None}
    assert not case_schema.is_valid(bad_case)
    assert not case_schema.is_valid({**bad_case, "faces": [[0, 1, 2]], "task": "dilate"})
    assert case_schema.is_valid({**bad_case, "faces": [[0, 1, 2]]})
    assert not answer_schema.is_valid({"faces": [[0, 1, 2]], "error": {"kind": "x", "message": "y"}})
    assert not answer_schema.is_valid({"faces": [[0, 1, 2, 3, 4]]})
    assert answer_schema.is_valid({"error": {"kind": "x", "message": "y"}})
