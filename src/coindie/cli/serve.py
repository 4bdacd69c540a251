"""``coindie serve``: the expert's review app on a local web server."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coindie.cli.common import exits_cleanly

#: The commands of this module; coindie.cli.app registers them.
commands = typer.Typer()


@commands.command("serve")
@exits_cleanly
def serve_command(
    source: Annotated[
        Path, typer.Argument(metavar="PROJECT_OR_GRAPH", help="A die-study project, or a bare graph.json.")
    ],
    port: Annotated[int, typer.Option(help="Port (0: any free port).")] = 8765,
    host: Annotated[str, typer.Option(help="Address to bind (default: this machine only).")] = "127.0.0.1",
    no_browser: Annotated[bool, typer.Option("--no-browser", help="Do not open a browser.")] = False,
    threshold: Annotated[
        float | None,
        typer.Option(
            help="Start at the paper's components of the probabilities above τ. Default: a project opens on "
            "its clusters as coindie cluster --auto makes them (each side's own cut at the slider's 0.5); "
            "a graph file at the paper's 0.95."
        ),
    ] = None,
    edits: Annotated[
        Path | None,
        typer.Option(help="Edit log of a bare graph file (default: GRAPH.edits.sqlite beside it)."),
    ] = None,
) -> None:
    """Review, correct and export the die clusters in the browser (first line: the URL with its token)."""
    import secrets
    import socket
    import sys
    import webbrowser

    import uvicorn

    from coindie.errors import ParameterError
    from coindie.serve import create_app, open_source

    if threshold is not None and not 0.0 <= threshold <= 1.0:
        raise ParameterError(f"--threshold must be in [0, 1], got {threshold}")
    review = open_source(source, threshold=threshold, edits=edits)
    token = secrets.token_urlsafe(24)
    sock = socket.socket(socket.AF_INET6 if ":" in host else socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        sock.bind((host, port))
    except OSError as error:
        raise ParameterError(f"cannot listen on {host}:{port} ({error.strerror})") from None
    sock.listen(128)  # connections made as soon as the URL is printed wait for the server
    bound = sock.getsockname()[1]
    shown = "127.0.0.1" if host in ("0.0.0.0", "::") else host
    url = f"http://{shown}:{bound}/?token={token}"
    _ = review.layout  # computed before the first request
    print(url, flush=True)  # the first line: scripts and tests read it
    print(
        f"coindie review of {review.name}: {review.graph.n_nodes} faces, {review.graph.n_edges} links, "
        f"{review.log.last_seq()} edits in the log; start: {review.how}; Ctrl-C stops",
        file=sys.stderr,
        flush=True,
    )
    hosts = {host, shown, socket.gethostname()} if host not in ("127.0.0.1", "localhost") else set()
    application = create_app(review, token, hosts)
    if not no_browser:
        webbrowser.open(url)
    config = uvicorn.Config(application, log_level="warning", access_log=False)
    uvicorn.Server(config).run(sockets=[sock])
