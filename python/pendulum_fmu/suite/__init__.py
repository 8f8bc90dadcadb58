"""The hard cases of Pendulum.fmu and of the split pendulum, run by an importer or engine and
judged, with reports as CI reads them (``pendulum-fmu suite``; docs/suite.md).

::

    from pathlib import Path
    from pendulum_fmu.suite import adapters, cases, session
    results = session.run_and_report(adapters.engine("fmpy"), cases.select("cs2-*"), Path("out"))
    print(all(r.status == "passed" for r in results))

Modules: ``cases`` (the registry, read from ``cases.csv``, which CMake also reads to ship the
cases in the FMUs), ``experiment`` (a case as an engine runs it), ``adapters`` (built-in
engines, a command template, a folder of results), ``engine_child`` and ``container_child``
(the built-in engines, each run in a process of its own), ``process`` (a command with a time
limit), ``judging`` (the judge and the split judge on a result), ``runner`` (the cases in
turn), ``junit``, ``figures`` and ``reports`` (JUnit XML, the HTML page, the JSON), ``session``
(one run and its reports), ``compatibility`` (every adapter against every case, for the docs).
"""
