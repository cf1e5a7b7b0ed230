"""The thesis reproduced: an application built on the polymimic library.

``polymimic reproduce`` runs the stages of :mod:`~polymimic.reproduce.stages` into a run
directory and writes ``results.json`` and a report beside the thesis's published numbers.
Nothing in the library imports this package; it imports the library and the run machinery
every application shares (:mod:`polymimic.runs`: the config, the roster, the run directory's
house, the task backends, progress bars, Markdown to HTML, mean ± sd).

==============  ==========================================================================
module          what it holds
==============  ==========================================================================
``rundir``      the run directory: where each stage's outputs live
``stages``      self-observe, record, train, segment, learn, evaluate, report
``experiments`` the learning trials and the evaluations, as tasks
``results``     ``results.json`` gathered from a run
``report``      ``report.md`` and ``report.html``, beside the thesis's numbers
``figures``     the report's plots
``thesis``      the thesis's published numbers
==============  ==========================================================================
"""
