"""The Python example of the repository's README.md, run as a doctest, so that the
README cannot go stale: every `>>>` line runs and every output shown must be the
package's. It runs in a scratch directory holding a copy of `tests/data/meshes`, so the
README's relative paths read the repository's meshes and its outputs land there."""

import doctest
import os
import shutil

from conftest import DATA, ROOT


def readme_example() -> tuple[str, int]:
    """The text between `<!-- python-example -->` and `<!-- /python-example -->`, and the
    line number of the opening marker."""
    lines = (ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    starts = [i for i, l in enumerate(lines) if l.strip() == "<!-- python-example -->"]
    ends = [i for i, l in enumerate(lines) if l.strip() == "<!-- /python-example -->"]
    assert len(starts) == 1 and len(ends) == 1 and starts[0] < ends[0], \
        "README.md: expected one <!-- python-example --> ... <!-- /python-example --> block"
    # Fences become empty lines, so that doctest's line numbers are the README's.
    body = ["" if l.startswith("```") else l for l in lines[starts[0] + 1:ends[0]]]
    return "\n".join(body) + "\n", starts[0] + 1


def test_readme_python_example_runs_as_shown(tmp_path):
    text, line = readme_example()
    test = doctest.DocTestParser().get_doctest(text, {}, "README.md", str(ROOT / "README.md"),
                                               line)
    assert test.examples, "README.md: the Python block has no >>> examples"
    shutil.copytree(DATA, tmp_path / "tests" / "data" / "meshes")
    cwd = os.getcwd()
    os.chdir(tmp_path)
    report = []
    try:
        runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
        result = runner.run(test, out=report.append)
    finally:
        os.chdir(cwd)
    assert result.failed == 0, f"README.md: {result.failed} of {result.attempted} " \
        "lines of the Python example differ:\n" + "".join(report)
