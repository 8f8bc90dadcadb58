"""The structure the JUnit XML schema (the Ant/Jenkins ``junit-10.xsd`` that CI systems follow)
asks of a report, checked with ``xml.etree``: no JUnit reading library is installed here."""

from __future__ import annotations

import xml.etree.ElementTree as ET

TESTSUITE_REQUIRED = ("name", "tests")
TESTCASE_REQUIRED = ("name", "classname")
TESTCASE_CHILDREN = {"properties", "skipped", "error", "failure", "system-out", "system-err"}


def _count(element: ET.Element, name: str) -> int:
    text = element.get(name, "0")
    assert text.isdigit(), f"<{element.tag} {name}={text!r}>: not a count"
    return int(text)


def _seconds(element: ET.Element) -> None:
    if element.get("time") is not None:
        assert float(element.get("time", "")) >= 0, element.get("time")


def check(root: ET.Element) -> dict[str, ET.Element]:
    """Assert the structure; return the test cases by name."""
    assert root.tag == "testsuites", root.tag
    cases: dict[str, ET.Element] = {}
    totals = {"tests": 0, "failures": 0, "errors": 0}
    for suite in root:
        assert suite.tag == "testsuite", suite.tag
        for name in TESTSUITE_REQUIRED:
            assert suite.get(name) is not None, f"<testsuite> without {name}"
        _seconds(suite)
        found = {"tests": 0, "failures": 0, "errors": 0}
        for child in suite:
            if child.tag == "properties":
                for prop in child:
                    assert prop.tag == "property" and prop.get("name") and prop.get("value") is not None
                continue
            assert child.tag == "testcase", child.tag
            for name in TESTCASE_REQUIRED:
                assert child.get(name), f"<testcase> without {name}"
            _seconds(child)
            tags = [c.tag for c in child]
            assert set(tags) <= TESTCASE_CHILDREN, tags
            assert tags.count("failure") + tags.count("error") <= 1, tags
            for verdict in child:
                if verdict.tag in ("failure", "error"):
                    assert verdict.get("message"), f"{child.get('name')}: <{verdict.tag}> without a message"
            found["tests"] += 1
            found["failures"] += tags.count("failure")
            found["errors"] += tags.count("error")
            assert child.get("name") not in cases
            cases[child.get("name", "")] = child
        for name, value in found.items():
            assert _count(suite, name) == value, (name, suite.get(name), value)
            totals[name] += value
    for name, value in totals.items():
        if root.get(name) is not None:
            assert _count(root, name) == value, (name, root.get(name), value)
    return cases


def properties(case: ET.Element) -> dict[str, str]:
    """A test case's properties by name."""
    holder = case.find("properties")
    return {} if holder is None else {p.get("name", ""): p.get("value", "") for p in holder}
