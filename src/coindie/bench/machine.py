"""The machine line every benchmark report carries (timings mean little without it)."""

from __future__ import annotations

import os
import platform


def describe_machine(workers: int) -> str:
    """CPU model, architecture, cores, worker processes (one BLAS thread each: coindie's default), Python."""
    cpu = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as handle:
            names = [line.split(":", 1)[1].strip() for line in handle if line.startswith("model name")]
        cpu = names[0] if names else cpu
    except OSError:
        pass
    return (
        f"{cpu} ({platform.machine()}), {os.cpu_count()} cores, {workers} worker process(es) of one BLAS "
        f"thread, Python {platform.python_version()}"
    )
