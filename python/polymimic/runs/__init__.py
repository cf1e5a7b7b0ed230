"""The machinery every application stands on: it imports the library, and the applications
(``polymimic.reproduce``, ``polymimic.benchmark``) import it; it imports no application.

==================  ======================================================================
module              what it holds
==================  ======================================================================
``config``          every parameter of a run (:class:`RunConfig`), TOML in and out, and the
                    checks every application's config is read with
``roster``          who takes part: the thesis's demonstrators, experiments and controls
``roster_config``   a config's own demonstrators, bodies and experiments
``rundir``          a run's directory: the manifest, the lock, datasets, models and plots
``backends``        where tasks run: a local process pool or Ray
``progress``        progress bars
``markdown``        Markdown to one self-contained HTML file
``stats``           mean ± sd, and how a report writes it
==================  ======================================================================
"""
