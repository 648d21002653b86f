"""fitfeel from Python: scenes, skin model shapes as NumPy arrays, runs and fit studies.

    import fitfeel
    print(fitfeel.validate("scenarios/paper-case1-h7js6.yaml"))
    trace, summary = fitfeel.run("scenarios/paper-case1-h7js6.yaml")  # trace.csv's columns
    shapes = fitfeel.skin_model_shapes("scenarios/paper-case1-h7js6.yaml", seed=3)

Errors in a scenario raise fitfeel.ScenarioError (a fitfeel.UserError, a ValueError) with the
message `fitfeel validate` prints: file:line:column, key path, expected, found. A study spread over
a Dask cluster: `/usr/bin/python3 -m fitfeel.study` (workers: `fitfeel-worker`), or
fitfeel.study.run_on_dask (fitfeel/study.py); on this machine's threads: fitfeel.study_on_threads.
docs/embedding.md has the rest.
"""
from ._fitfeel import (STAGES, ScenarioError, UserError, run, skin_model_shapes,
                       study_on_threads, study_pair, validate, write_study)

__all__ = ["STAGES", "ScenarioError", "UserError", "run", "skin_model_shapes", "study_on_threads",
           "study_pair", "validate", "write_study"]
