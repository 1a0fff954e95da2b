"""``trex course``: a whole course (lectures, scenes, slides, an exercise set per student)
rendered as tasks on Dask distributed.

:mod:`~trex.course.schema` reads and checks the TOML course file, :mod:`~trex.course.tasks`
expands it into fingerprinted tasks (checking every scene and polygon first),
:mod:`~trex.course.work` is what a worker does for each, :mod:`~trex.course.run` submits
them and waits, :mod:`~trex.course.manifest` keeps ``course.json``, and
:mod:`~trex.course.command` is the command line. See docs/course.md.
"""
