"""The ``coindie`` command line. Thin: it parses arguments, calls the library, prints results.

Heavy modules are imported inside the commands so that ``coindie --help`` stays fast. Errors that
coindie raises on purpose (``CoinDieError``) end the command with exit code 2 and a one-line message.
"""

from __future__ import annotations

from coindie.cli.app import app, main

__all__ = ["app", "main"]
