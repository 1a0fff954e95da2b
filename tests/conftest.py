"""Suite-wide settings: reproducible hypothesis runs, and slow tests only on request."""

import pytest
from hypothesis import HealthCheck, settings

# Derandomized: CI and every developer see the same examples, so a red run reproduces.
settings.register_profile(
    "trex", derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.load_profile("trex")


def pytest_addoption(parser):
    parser.addoption("--runslow", action="store_true", help="also run tests marked slow")


def pytest_collection_modifyitems(config, items):
    if config.getoption("--runslow"):
        return
    skip = pytest.mark.skip(reason="slow: run with --runslow")
    for item in items:
        if "slow" in item.keywords:
            item.add_marker(skip)
