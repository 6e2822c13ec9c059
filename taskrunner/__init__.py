"""taskrunner: declarative task scripting and a behaviour-tree runtime for robot-arm cells."""

import os as _os

# Small matrices everywhere: OpenBLAS spreading a product over threads costs 10-50 ms per
# call on a loaded 2-core machine (measured in toppra's setup). Set before numpy loads;
# an explicit setting in the environment wins.
_os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

__version__ = "0.1.0"
