"""pride.__version__: CMake's project(VERSION), the one `pride --version` prints."""
import re
import subprocess

import pride
from conftest import REPO, pride_exe


def test_version_is_the_projects():
    cmake = (REPO / "CMakeLists.txt").read_text()
    declared = re.search(r"^project\(pride VERSION ([0-9][0-9.]*)\b", cmake, flags=re.M).group(1)
    assert pride.__version__ == declared
    assert "__version__" in pride.__all__


def test_version_is_the_commands():
    out = subprocess.run([pride_exe(), "--version"], capture_output=True, text=True, check=True).stdout
    assert out == f"pride {pride.__version__}\n"
