#!/usr/bin/env python3
"""The conformance report's HTML (suite conformance, test conform-report):
runs fixgl-conform on the cases of a small tag that holds entries of the
known-differences list and checks index.html:

- every differing case listed in the list shows its reason from the list,
  in its section and in the table of all cases;
- the summary's row of the tag gives the same counts as the summary the
  runner printed, the tag and its counts link to #tag-TAG[:STATUS], and the
  table of all cases has the anchor tag-TAG on the tag's first row;
- the filter controls (tag and status) and their script are in the page,
  which refers to nothing outside its directory;
- a run given a list without one of those cases shows it "unlisted" (red)
  and fails.

usage: check_report.py FIXGL-CONFORM KNOWN-DIFFERENCES OUT-DIR TAG
"""
import html
import os
import re
import shutil
import subprocess
import sys


def fail(msg):
    print("check_report: " + msg, file=sys.stderr)
    sys.exit(1)


def run(conform, known, report, tag=None, cases=()):
    args = [conform, "--no-random", "--jobs", "2", "--known", known, "--report", report]
    if tag:
        args += ["--tag", tag]
    for c in cases:
        args += ["--case", c]
    print("$ " + " ".join(args), flush=True)
    p = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(p.stdout[-3000:])
    return p.returncode, p.stdout


def main():
    if len(sys.argv) != 5:
        fail(__doc__)
    conform, known_path, out, tag = sys.argv[1:]
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)

    listed = subprocess.run([conform, "--no-random", "--list", "--tag", tag], stdout=subprocess.PIPE,
                            text=True, check=True).stdout
    names = [line.split("\t")[0] for line in listed.splitlines() if line]
    reasons = {}
    with open(known_path) as f:
        for line in f:
            if line.startswith("#") or not line.split():
                continue
            name, _, reason = line.strip().partition(" ")
            reasons[name] = reason.strip()
    known_here = [n for n in names if n in reasons]
    if not known_here:
        fail("tag %s has no case in %s: choose another tag" % (tag, known_path))

    rc, stdout = run(conform, known_path, os.path.join(out, "listed"), tag=tag)
    if rc != 0:
        fail("fixgl-conform --tag %s with the list exited %d" % (tag, rc))
    page = open(os.path.join(out, "listed", "index.html")).read()
    failures = []

    # the reasons, in each case's section and in the table's row
    for name in known_here:
        reason = html.escape(reasons[name], quote=True)
        stem = re.sub(r"[^A-Za-z0-9_-]", "_", name)
        sec = re.search(r'<section id="%s">(.*?)</section>' % re.escape(stem), page, re.S)
        if not sec:
            failures.append("%s (listed) has no section" % name)
        elif reason not in sec.group(1):
            failures.append("the section of %s does not show its reason" % name)
        row = re.search(r'<tr[^>]*data-status="[a-z]+" data-known="listed"><td>(?:<a id="[^"]*"></a>)*'
                        r'<a href="#%s">%s</a>.*?</tr>' % (re.escape(stem), re.escape(html.escape(name))),
                        page)
        if not row or reason not in row.group(0):
            failures.append("the row of %s in the table of all cases does not show its reason" % name)

    # the tag's counts: the same as the printed summary
    m = re.search(r"^%s +(\d+) +(\d+) +(\d+) +(\d+) +(\d+) +(\d+)$" % re.escape(tag), stdout, re.M)
    if not m:
        fail("the printed summary has no row for %s" % tag)
    cases, exact, agrees, differs, blank, error = (int(x) for x in m.groups())
    if cases != len(names) or differs < len(known_here):
        failures.append("printed counts of %s: %d cases, %d differ (expected %d cases, >= %d differ)"
                        % (tag, cases, differs, len(names), len(known_here)))
    row = re.search(r'<tr><td><a href="#tag-%s">%s</a></td>(.*?)</tr>' % (re.escape(tag), re.escape(tag)),
                    page)
    if not row:
        failures.append("the summary has no linked row for %s" % tag)
    else:
        cells = re.findall(r"<td[^>]*>(.*?)</td>", row.group(1))
        values = [int(re.sub(r"<[^>]*>", "", c)) for c in cells[:7]]
        expected = [cases, exact, agrees, differs, blank, error, 0]
        if values != expected:
            failures.append("summary row of %s: %s, printed %s" % (tag, values, expected))
        if differs and '<a href="#tag-%s:differs">%d</a>' % (tag, differs) not in row.group(1):
            failures.append("the differs count of %s does not link to its rows" % tag)
    if 'id="tag-%s"' % tag not in page:
        failures.append("no anchor tag-%s in the table of all cases" % tag)

    # the filter controls, in the page
    for needle in ('<select id="filter-tag"', '<option>%s</option>' % tag, '<select id="filter-status"',
                   '<option>differs</option>', '<option value="unlisted">unlisted</option>',
                   'function fcFilter()', "window.addEventListener('hashchange'",
                   'data-tags="', 'data-status="'):
        if needle not in page:
            failures.append("the page lacks %s" % needle)
    for ref in re.findall(r'(?:src|href)="([^"#][^"]*)"', page):
        if "://" in ref or ref.startswith("/") or not os.path.exists(os.path.join(out, "listed", ref)):
            failures.append("the page refers to %s, not in its directory" % ref)
    if "<script src" in page:
        failures.append("the page loads a script")

    # without the first case's entry: unlisted, in red, and the run fails
    drop = known_here[0]
    partial = os.path.join(out, "partial-known.txt")
    with open(known_path) as f, open(partial, "w") as g:
        for line in f:
            if line.split()[:1] != [drop]:
                g.write(line)
    rc, _ = run(conform, partial, os.path.join(out, "unlisted"), cases=[drop])
    page2 = open(os.path.join(out, "unlisted", "index.html")).read()
    if rc != 1:
        failures.append("a run with %s unlisted exited %d, not 1" % (drop, rc))
    if '<span class="unlisted">unlisted</span>' not in page2 or ".unlisted{color:#d00" not in page2:
        failures.append("%s unlisted is not shown \"unlisted\" in red" % drop)
    if html.escape(reasons[drop], quote=True) in page2:
        failures.append("the unlisted run still shows the reason of %s" % drop)

    for f in failures:
        print("check_report: " + f, file=sys.stderr)
    if failures:
        return 1
    print("report of tag %s: %d cases (%d exact, %d differ), %d listed with their reasons, the "
          "filter controls, an unlisted case in red" % (tag, cases, exact, differs, len(known_here)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
