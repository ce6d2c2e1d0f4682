"""An unknown algorithm or problem names the close ones, from Python as from the command line
(one function, framework/close_names.hpp)."""
import pytest

import pride
from conftest import cli


def one_line(e):
    text = str(e.value)
    assert "\n" not in text
    return text


def test_unknown_problem_names_close_ones():
    with pytest.raises(ValueError) as e:
        pride.minimize("pso", "rastrign", dim=2, evals=100)
    assert one_line(e) == "problem: unknown problem 'rastrign'; did you mean 'rastrigin'?"
    with pytest.raises(ValueError) as e:
        pride.Problem("spher", 2)
    assert one_line(e) == "problem: unknown problem 'spher'; did you mean 'sphere'? (see pride.problems())"
    # A constrained suite's number out of range: its neighbours.
    with pytest.raises(ValueError, match=r"^problem: unknown problem 'cec2006-g25'; did you mean 'cec2006-g05'"):
        pride.minimize("pso", "cec2006-g25", evals=100)
    with pytest.raises(ValueError) as e:
        pride.minimize("pso", "nothing-like-it", dim=2, evals=100)
    assert one_line(e) == "problem: unknown problem 'nothing-like-it'"
    with pytest.raises(ValueError, match=r"^problems\[0\]: .*unknown problem 'spher'; did you mean 'sphere'\?"):
        pride.Campaign("c", seeds=1, evals=10, algorithms=["pso"],
                       problems=[{"id": "s", "problem": "spher", "dim": 2}])


def test_unknown_algorithm_names_close_ones():
    with pytest.raises(ValueError) as e:
        pride.minimize("psoo", "sphere", dim=2, evals=100)
    assert one_line(e).startswith("algo: unknown algorithm 'psoo'; did you mean 'pso'")
    assert "(known: " in one_line(e)
    with pytest.raises(ValueError) as e:
        pride.minimize("nope", "sphere", dim=2, evals=100)
    assert one_line(e).startswith("algo: unknown algorithm 'nope' (known: ")


def test_the_command_line_names_them_too():
    p = cli("run", "--problem", "rastrign", "--dim", "2", "--algo", "pso", check=False)
    assert p.returncode == 2 and p.stdout == ""
    assert p.stderr == "pride: --problem: unknown problem 'rastrign'; did you mean 'rastrigin'?\n"
    p = cli("run", "--problem", "sphere", "--dim", "2", "--algo", "psoo", check=False)
    assert p.returncode == 2
    assert p.stderr.startswith("pride: --algo: unknown algorithm 'psoo'; did you mean 'pso'")
