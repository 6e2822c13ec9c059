"""taskrunner: declarative task scripting and a behaviour-tree runtime for robot-arm cells."""

__version__ = "0.1.0"
