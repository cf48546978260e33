"""One module per `acconform` subcommand: add_arguments(parser) and run(args) -> exit code.

Keep imports at module level light; import the port, the oracle or Hypothesis inside run().
"""
