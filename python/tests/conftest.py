"""The tests import the installed package (``pip install ./python``), never the source tree
``python/shadow_aliasing``, which holds no compiled extension: Python started in ``python/`` puts
that directory first on ``sys.path``, and its ``shadow_aliasing`` would shadow the installed one
(a stale extension left there once failed test_fast_path.py). So the tests run the same from the
repository root, from ``python/`` or from ``python/tests``."""
import os
import sys

_SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path[:] = [p for p in sys.path if os.path.abspath(p or os.curdir) != _SOURCE]
