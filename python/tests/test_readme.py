"""Every Python use quoted in README.md and docs/*.md runs (their `rockroll` commands are
checked by app/test/test_DocCommands.cpp): each fenced ```python block as a script, and each line of a
fenced ```sh block that starts with `PYTHONPATH=build/python /usr/bin/python3` as a shell
command; both in a fresh directory holding links to scenarios/ and examples/, with
PYTHONPATH pointing at this build's module."""
import os
import re
import subprocess
import sys

from conftest import SOURCE_DIR

PREFIX = "PYTHONPATH=build/python /usr/bin/python3 "


def quoted():
    files = [SOURCE_DIR / "README.md"] + sorted((SOURCE_DIR / "docs").glob("*.md"))
    text = "\n".join(f.read_text() for f in files)
    blocks = re.findall(r"^```(\w*)\n(.*?)^```", text, flags=re.S | re.M)
    scripts = [body for lang, body in blocks if lang == "python"]
    shell = [re.sub(r"\s+#.*$", "", line) for lang, body in blocks if lang == "sh"
             for line in body.splitlines() if line.startswith(PREFIX)]
    return scripts, shell


def test_readme_python_uses_run(tmp_path):
    scripts, shell = quoted()
    assert scripts and shell, "README.md and docs/ quote no Python use"
    for name in ("scenarios", "examples"):
        (tmp_path / name).symlink_to(SOURCE_DIR / name)
    env = dict(os.environ)  # PYTHONPATH made absolute: the commands run in tmp_path
    env["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p) for p in env.get("PYTHONPATH", "").split(os.pathsep) if p)
    for script in scripts:
        p = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True, text=True, env=env)
        assert p.returncode == 0, f"{script}\n{p.stderr}"
        assert p.stdout
    for line in shell:
        command = f"{sys.executable} {line[len(PREFIX):]}"
        p = subprocess.run(command, shell=True, cwd=tmp_path, capture_output=True, text=True, env=env)
        assert p.returncode == 0, f"{line}\n{p.stderr}"
