#!/usr/bin/env python3
"""repository_map.py's check on small trees written here, and map.txt
against the real tree. Standard library only."""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import repository_map as rm  # noqa: E402

FILES = ["README.md", "core/a.cpp", "core/contact/b.cpp", "core/exact/c.cpp", "core/solver.cpp",
         "doc/index.md", ".ci/run"]


class Check(unittest.TestCase):
    def test_a_complete_map_passes(self):
        self.assertEqual(rm.problems(["core/", "core/contact/", "core/exact/", "core/solver.*", "doc/"],
                                     FILES), [])

    def test_a_missing_sibling_fails(self):
        self.assertEqual(rm.problems(["core/", "core/contact/", "doc/"], FILES),
                         ["core/exact/: its siblings have entries, it has none"])

    def test_a_missing_top_level_folder_fails(self):
        self.assertEqual(rm.problems(["core/"], FILES), ["doc/: a top-level folder without an entry"])

    def test_a_path_that_does_not_exist_fails(self):
        self.assertEqual(rm.problems(["core/", "core/normal/", "core/contact/", "core/exact/",
                                      "core/model.hpp", "doc/"], FILES),
                         ["core/normal/: no such folder", "core/model.hpp: no such file"])

    def test_render_nests_and_wraps(self):
        text = rm.render([("core/", "the core"), ("core/contact/", "shared " * 20)])
        lines = text.split("\n")
        self.assertTrue(lines[0].startswith("core/") and lines[1].startswith("  contact/"))
        self.assertTrue(all(len(line) <= rm.WIDTH for line in lines))
        self.assertTrue(lines[2].startswith(" " * len("  contact/  ")))


class RealTree(unittest.TestCase):
    def test_map_matches_the_tree(self):
        source = os.path.join(rm.HERE, "..", "..")
        items = rm.entries(os.path.join(rm.HERE, "map.txt"))
        self.assertEqual(rm.problems([n for n, _ in items], rm.tracked_files(source)), [])


if __name__ == "__main__":
    unittest.main()
