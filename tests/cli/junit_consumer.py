"""facet batch's JUnit report as a JUnit consumer reads it: junitparser
(Debian's python3-junitparser, the library CI tools merge and read reports
with) loads it, and its suites, counts and each case's result are the ones
expected.
    junit_consumer.py REPORT TESTS FAILURES ERRORS SKIPPED CASE=RESULT ...
RESULT is passed, failure, error or skipped; CASE a test case's name."""
import sys

from junitparser import Error, Failure, JUnitXml, Skipped

report, tests, failures, errors, skipped = sys.argv[1], *map(int, sys.argv[2:6])
expected = dict(word.split("=", 1) for word in sys.argv[6:])

xml = JUnitXml.fromfile(report)
suites = list(xml)
assert len(suites) == 1, f"{len(suites)} test suites, not 1"
suite = suites[0]
counts = (suite.tests, suite.failures, suite.errors, suite.skipped)
assert counts == (tests, failures, errors, skipped), f"tests, failures, errors, skipped: {counts}"
cases = {case.name: case for case in suite}
assert len(cases) == tests, f"{len(cases)} named test cases, not {tests}"
kinds = {Failure: "failure", Error: "error", Skipped: "skipped"}
for name, result in expected.items():
    assert name in cases, f"no test case {name!r} (cases: {sorted(cases)})"
    got = [kinds[type(r)] for r in cases[name].result if type(r) in kinds] or ["passed"]
    assert got == [result], f"{name}: {got[0]}, not {result}"
    if result in ("failure", "error"):
        assert cases[name].result[0].message, f"{name}: a {result} without a message"
print(f"junitparser read {report}: {counts[0]} cases, {counts[1]} failures, {counts[2]} errors, {counts[3]} skipped")
