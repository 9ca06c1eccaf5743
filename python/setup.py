"""Builds the pure-Python package against an installed libcreepwork: the
environment variable CREEPWORK_PREFIX names the prefix it was installed to
(cmake --install ... --prefix P). The layout is generated from that
prefix's creepwork.h, and _config.py records that prefix's library, as
CMake's installation does for the package it installs itself."""

import glob
import os
import sys

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import generate_layout  # noqa: E402  (beside this file)


def installed():
    prefix = os.environ.get("CREEPWORK_PREFIX")
    if not prefix:
        sys.exit("creepwork: set CREEPWORK_PREFIX to the prefix libcreepwork was installed to "
                 "(cmake --install <build> --prefix <prefix>), e.g.\n"
                 "  CREEPWORK_PREFIX=$HOME/opt/creepwork python3 -m pip install "
                 "--no-build-isolation ./python")
    prefix = os.path.abspath(os.path.expanduser(prefix))
    header = os.path.join(prefix, "include", "creepwork", "creepwork.h")
    libraries = sorted(glob.glob(os.path.join(prefix, "lib*", "libcreepwork.so.*")) +
                       glob.glob(os.path.join(prefix, "lib", "*", "libcreepwork.so.*")),
                       key=len)
    if not os.path.isfile(header) or not libraries:
        sys.exit("creepwork: no include/creepwork/creepwork.h and lib*/libcreepwork.so.* under "
                 "CREEPWORK_PREFIX=%s" % prefix)
    return header, libraries[0]  # the shortest name: the soname link libcreepwork.so.1


def layout():
    header, _ = installed()
    return generate_layout.parse_header(generate_layout.read_header(header),
                                        os.path.basename(header))


class BuildPy(build_py):
    """Copies the package and writes its generated _layout.py and _config.py."""

    def run(self):
        super().run()
        _, library = installed()
        target = os.path.join(self.build_lib, "creepwork")
        generate_layout.write_if_changed(os.path.join(target, "_layout.py"),
                                         generate_layout.python_source(layout()))
        generate_layout.write_if_changed(
            os.path.join(target, "_config.py"),
            "# Written by setup.py: the library this package loads.\nLIBRARY = %r\n" % library)


constants = layout()["constants"]
setup(version="%d.%d.%d" % (constants["CW_VERSION_MAJOR"], constants["CW_VERSION_MINOR"],
                            constants["CW_VERSION_PATCH"]),
      cmdclass={"build_py": BuildPy})
