"""One module per ``ballscrew`` subcommand; ``ballscrew.cli`` registers them.

Importing a command module is cheap (``--help`` imports them all): the analysis it runs is
imported inside its command function.
"""
