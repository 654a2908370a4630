"""One module per ``ballscrew`` subcommand; ``ballscrew.cli`` registers them."""
