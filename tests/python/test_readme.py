"""The Python example of README.md runs as written (the line is read from README.md, so the two
cannot drift apart) and prints what it promises."""
import os
import re
import subprocess
import unittest

from support import SOURCE_DIR


class ReadmeExample(unittest.TestCase):
    def test_example_line_runs(self):
        with open(os.path.join(SOURCE_DIR, "README.md"), encoding="utf-8") as f:
            lines = [l.strip() for l in f if l.strip().startswith("PYTHONPATH=")]
        self.assertEqual(len(lines), 1, "README.md must hold one 'PYTHONPATH=... python3 -c' line")
        line = lines[0]
        module_dir = os.environ["PYTHONPATH"].split(os.pathsep)[0]
        written = re.match(r"PYTHONPATH=(\S+) ", line).group(1)
        env = dict(os.environ)
        if os.path.realpath(os.path.join(SOURCE_DIR, written)) != os.path.realpath(module_dir):
            # A build tree other than build/: the same line, pointed at this tree's module.
            line = line.replace("PYTHONPATH=" + written, "PYTHONPATH=" + module_dir, 1)
        p = subprocess.run(["bash", "-c", line], cwd=SOURCE_DIR, capture_output=True, text=True,
                           timeout=300, env=env, check=False)
        self.assertEqual(p.returncode, 0, p.stderr)
        # It prints the map's shape, the number of objects and the room's area.
        self.assertRegex(p.stdout.strip(), r"^\(\d+, \d+\) \d+ \d+\.\d+$")


if __name__ == "__main__":
    unittest.main()
