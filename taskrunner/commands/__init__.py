"""The bodies of ``run-task``'s commands, a module per family; ``taskrunner.cli`` only parses
the command line and dispatches here. Each module imports its heavy dependencies inside
the command that needs them, so that ``run-task --help`` stays fast."""
