"""The thesis reproduced: an application built on the polymimic library.

``polymimic reproduce`` runs the stages of :mod:`~polymimic.reproduce.stages` into a run
directory and writes ``results.json`` and a report beside the thesis's published numbers.
Nothing in the library imports this package; it imports the library.

==============  ==========================================================================
module          what it holds
==============  ==========================================================================
``config``      every parameter of a run (:class:`RunConfig`), TOML in and out
``rundir``      the run directory: where each stage's outputs live, the manifest
``roster``      who takes part: the demonstrators, the three experiments, the controls
``stages``      self-observe, record, train, segment, learn, evaluate, report
``experiments`` the learning trials and the evaluations, as tasks
``backends``    where tasks run: a local process pool or Ray
``results``     ``results.json`` gathered from a run
``report``      ``report.md`` and ``report.html``, beside the thesis's numbers
``figures``     the report's plots
``thesis``      the thesis's published numbers
``markdown``    Markdown to one self-contained HTML file
``progress``    progress bars
==============  ==========================================================================
"""
