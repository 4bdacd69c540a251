"""Commands that look at one scan: ``info`` and ``render`` (wired once the readers exist)."""
