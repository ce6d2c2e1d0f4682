"""cocopp, run from its source, reads what `pride export STORE --coco DIR` wrote of a bbob, a
bbob-mixint and a bbob-constrained campaign as the store holds the runs (scripts/cocopp_check.py --store): each run
one .info entry with its instance and evaluations, paired with its blocks, and at every target
of cocopp the evaluations of the run's COCO trace (bbob-constrained: f and constraint evaluations
summed, as cocopp counts them). PRIDE_COCOPP_SRC names the src/cocopp folder of a
numbbo/coco-postprocess checkout; without it the test is skipped."""
import os
import subprocess

import pytest

from conftest import REPO, cli

CAMPAIGN = """name = "cocopp-{suite}"
seeds = 2
[budget]
evaluations_per_dim = 200
[[suite]]
name = "{suite}"
functions = [{functions}]
instances = [1, 2, 3]
dimensions = [{dims}]
[[algorithm]]
id = "de"
type = "de"
pop = 10
[[algorithm]]
id = "pso"
type = "pso"
pop = 10
"""


@pytest.mark.parametrize("suite, functions, dims", [("bbob", "1, 8", "2, 3"), ("bbob-mixint", "2, 15", "5, 10"),
                                                    ("bbob-constrained", "1, 43", "2, 3")])
def test_cocopp_reads_the_export_as_the_store_holds_it(tmp_path, suite, functions, dims):
    source = os.environ.get("PRIDE_COCOPP_SRC")
    if not source or not os.path.isdir(source):
        pytest.skip("needs PRIDE_COCOPP_SRC, the src/cocopp folder of a numbbo/coco-postprocess checkout")
    toml = tmp_path / "c.toml"
    toml.write_text(CAMPAIGN.format(suite=suite, functions=functions, dims=dims))
    store, coco = tmp_path / "c.sqlite", tmp_path / "coco"
    cli("bench", toml, "--out", store)
    cli("export", store, "--coco", coco)
    p = subprocess.run(["/usr/bin/python3", str(REPO / "scripts" / "cocopp_check.py"), source, str(coco), "--store",
                        str(store)], capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    # 2 algorithms x 2 functions x 2 dimensions; 3 instances x 2 seeds in each.
    assert f"cocopp read 8 {suite} data sets; 48 runs and " in p.stdout, p.stdout
