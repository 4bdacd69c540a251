"""Numismatic results from die clusters: the die-link network, the original number of dies, the catalogue.

- :mod:`coindie.numismatics.sources`: the dies of each face, from a project (its clusters) or label CSVs;
- :mod:`coindie.numismatics.die_links`: the bipartite network obverse die <-> reverse die, its chains and
  their seriation; CSV / GraphML / GEXF and a diagram;
- :mod:`coindie.numismatics.estimators`: n, d, d1, d2, coverage and the estimators of the original number
  of dies (Good, Esty, Chao1, ACE), each with its interval;
- :mod:`coindie.numismatics.accumulation`: the die-accumulation curve and its extrapolation;
- :mod:`coindie.numismatics.metadata`: a coin metadata CSV, summarised per die.
"""
