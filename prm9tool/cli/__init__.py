"""The command line: argument parsing, offline file tools, headless ``--batch`` and its report."""
