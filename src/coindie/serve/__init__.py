"""The expert's review app (``coindie serve``): verify, correct and export die clusters in the browser.

>>> from coindie.serve import open_source, create_app  # doctest: +SKIP
>>> app = create_app(open_source("study"), token="secret")  # doctest: +SKIP
"""

from coindie.serve.app import create_app
from coindie.serve.source import ReviewError, ReviewSource, open_source

__all__ = ["ReviewError", "ReviewSource", "create_app", "open_source"]
