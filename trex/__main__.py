"""``python -m trex`` runs the command line."""

from trex.cli import main

main()
