"""A die-study project: a folder with a SQLite database, the per-face cache, and every scored pair.

>>> from coindie.project import init_project, open_project
>>> project = init_project("study", "scans/")            # doctest: +SKIP
>>> run_project(project, workers=2)                      # doctest: +SKIP  (coindie.project.run)
>>> graph = open_project("study").probability_graph()    # doctest: +SKIP  (for coindie.clustering)

The layout (:mod:`coindie.project.store`): ``project.sqlite`` (WAL: readers such as ``coindie status`` never
block a run) and ``cache/`` (one ``.npz`` per face and parameter set, keyed by the scan file's content
hash). A run (:mod:`coindie.project.run`) does the per-face work once, plans the pairs of each side
(exhaustive, or the candidates of :mod:`coindie.candidates`), and scores them in batches on local processes
or a Dask cluster (:mod:`coindie.project.backends`); each batch is committed in one transaction, so an
interrupted run loses at most the batches in flight and a rerun repeats no committed pair.
"""

from coindie.project.store import Project, ProjectError, init_project, open_project

__all__ = ["Project", "ProjectError", "init_project", "open_project"]
