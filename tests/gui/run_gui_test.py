"""GUI test: the real ParaView GUI under Xvfb, the GeoLattice plugin, every GeoLattice filter created
from Filters > GeoLattice and applied with the Apply button, a screenshot at the end.

    GEOLATTICE_PLUGIN=<build>/lib/paraview-5.11/plugins/GeoLattice/GeoLattice.so \\
    GEOLATTICE_SOURCE_DIR=<source> python3 tests/gui/run_gui_test.py --screenshot out.png

How it works. Debian's ParaView 5.11 GUI cannot run Python test scripts (`--test-script=x.py` is
"played" but does nothing and the GUI exits 0: its QtTesting has no Python event source), and a
`--script` cannot fail the process. So this driver writes a QtTesting XML event file and runs

    xvfb-run -a -s "-screen 0 1280x1024x24" paraview --dr --plugin-search-paths=<plugin dir>
        --plugins=GeoLattice --test-script=<events.xml> --exit

(`--plugins=<full path>` does not load the plugin in 5.11; a name plus a search path does). The
events, played on the real widgets, are:

1. in the Python shell (`executeCommand` on its console): tests/gui/gui_setup.py checks the plugin's
   proxy definitions and the reader factory (an .off file opens with GL Mesh Reader) and opens the
   model with GL Mesh Reader;
2. for each filter of CHAIN: make its input the active source, activate Filters > GeoLattice > <filter>
   (playback fails if the GeoLattice sub-menu has no such action), for a filter with a second input
   pick it in the "Select Input" dialog (port button, pipeline item, OK), then press Apply;
3. in the Python shell: tests/gui/gui_check.py checks every filter's inputs and non-empty outputs,
   colours the part and the sequenced lattice and saves the screenshot.

The two scripts write JSON results; the process's exit code says whether playback succeeded.

With --print-part, the driver first runs the command line on the model (default: the bundled bunny) with
PRINT_PART_CLI, then plays: open the model (ParaView's own reader), Filters > GeoLattice > GL Print
Part, type PRINT_PART_PARAMETERS into its panel, Apply (once), select its Toolpath, Filters >
GeoLattice > GL Toolpath Replay, Apply; tests/gui/gui_print_part_check.py compares the Summary table
with the command line's report.json, checks the verdict annotation and plays the replay, and saves
the workbench, summary and replay screenshots into --screenshot-dir (docs/images for the user guide).

With --state, the driver instead saves a state with pvpython/geolattice_state.py, starts the GUI with
`--state=<it>` (the GUI's own state loading, as File > Load State) and runs tests/gui/gui_state_check.py
in the Python shell: every source of the state non-empty, the four coloured views, a screenshot.

Exit code 0 = pass, 1 = fail, 77 = skipped: no paraview GUI, or no X server can be made (xvfb-run or
Xvfb not on the PATH, or paraview still without a display after two tries; `xvfb-run -a` can hand the
same display to two runs starting together, hence the second try).
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from xml.sax.saxutils import quoteattr

SKIP = 77
HERE = os.path.dirname(os.path.abspath(__file__))
CONSOLE = "pqClientMainWindow/pythonShellDock/pythonShell/consoleWidget"
MENU = "pqClientMainWindow/menubar/menuFilters/GeoLattice"
APPLY = "pqClientMainWindow/propertiesDock/propertiesPanel/Accept"
DIALOG = "pqClientMainWindow/SelectInputDialog"
READER_NAME = "y_shape"  # registration name of the GL Mesh Reader made by gui_setup.py

# The GUI pipeline, in the order the filters are created from the menu:
# (filter, active source before the menu action (None: the filter made just before), {second input: source}).
CHAIN = [
    ("GLPlaceOnPlatform", READER_NAME, {}),
    ("GLTetrahedralizeSurface", None, {}),
    ("GLGeodesicDistanceFields", None, {}),
    ("GLCurvedLayerSlicer", None, {}),
    ("GLLatticeInfill", None, {}),
    ("GLSkeletonTree", None, {"TetMesh": "GLGeodesicDistanceFields1"}),
    ("GLPrintSequencer", "GLLatticeInfill1", {"Skeleton": "GLSkeletonTree1"}),
    ("GLCollisionVerifier", "GLPrintSequencer1", {}),
    ("GLToolpathPlanner", "GLPrintSequencer1", {"Skeleton": "GLSkeletonTree1"}),
    ("GLToolpathReplay", None, {}),
    ("GLOverhangAnalysis", "GLGeodesicDistanceFields1", {}),
    ("GLAutoOrient", "GLPlaceOnPlatform1", {}),
    ("GLSurfaceCheck", "GLPlaceOnPlatform1", {}),
    ("GLPedestal", "GLPlaceOnPlatform1", {}),
    # Last: its table opens a spreadsheet view, which becomes the active view. Its Verifier input is
    # optional, so the GUI asks for no second input (no Select Input dialog).
    ("GLPrintSummary", "GLToolpathPlanner1", {}),
    # One Apply: the whole pipeline again from the reader (its outputs go to the active view).
    ("GLPrintPart", READER_NAME, {}),
]
# Where the second inputs are in the "Select Input" dialog's pipeline tree (pqFlatTreeView rows from the
# server item down; an item with several output ports has one child per port): builtin server / y_shape /
# place / tets / fields, and ... / fields / layers / port "Layers" / lattice / skeleton. gui_check.py
# verifies that the inputs picked this way are the intended ones.
# --print-part: the command line's options and the same parameters typed into GL Print Part's panel.
PRINT_PART_CLI = ["--fit-size", "80", "--orient", "auto", "--until", "toolpath", "--replay-steps", "0"]
PRINT_PART_PARAMETERS = {"FitSize": 80.0, "Orient": 1}
TREE_ROWS = {"GLGeodesicDistanceFields1": "0/0/0/0/0|0", "GLSkeletonTree1": "0/0/0/0/0/0/0/0/0|0"}


def plugin_xml_texts(source_dir):
    """The texts of the plugin's XML files listed in plugin/CMakeLists.txt."""
    with open(os.path.join(source_dir, "plugin", "CMakeLists.txt")) as f:
        files = re.findall(r"(xml/\S+\.xml)", f.read())
    for rel in files:
        with open(os.path.join(source_dir, "plugin", rel)) as f:
            yield f.read()


def plugin_filters(source_dir):
    """{proxy name: (group, ShowInMenu category or None)} of the plugin's XML files."""
    found = {}
    for text in plugin_xml_texts(source_dir):
        for group, body in re.findall(r'<ProxyGroup name="(\w+)">(.*?)</ProxyGroup>', text, re.S):
            for name, proxy in re.findall(r'<SourceProxy name="(\w+)"(.*?)</SourceProxy>', body, re.S):
                category = re.search(r'<ShowInMenu[^>]*category="([^"]+)"', proxy)
                found[name] = (group, category.group(1) if category else None)
    return found


def none_array_properties(source_dir):
    """{filter: {property: none string}}: the array-selection properties (ArrayListDomain with a
    none_string) whose XML default is that none string, i.e. "no array" unless the user picks one."""
    found = {}
    for text in plugin_xml_texts(source_dir):
        for name, proxy in re.findall(r'<SourceProxy name="(\w+)"(.*?)</SourceProxy>', text, re.S):
            for prop, attributes, body in re.findall(
                    r'<StringVectorProperty name="(\w+)"([^>]*)>(.*?)</StringVectorProperty>', proxy, re.S):
                none = re.search(r'<ArrayListDomain[^>]*none_string="([^"]*)"', body)
                default = re.search(r'default_values="([^"]*)"', attributes)
                if none and default and re.split(r"[;\s]+", default.group(1).strip())[-1] == none.group(1):
                    found.setdefault(name, {})[prop] = none.group(1)
    return found


def event(obj, command, arguments=""):
    return "  <pqevent object=%s command=%s arguments=%s />" % (quoteattr(obj), quoteattr(command),
                                                                quoteattr(arguments))


def python_event(code):
    return event(CONSOLE, "executeCommand", code)


def run_file_code(path):
    return "exec(compile(open(%r).read(), %r, 'exec'))" % (path, path)


def write_events(path, chain):
    lines = ['<?xml version="1.0" ?>', "<pqevents>",
             python_event(run_file_code(os.path.join(HERE, "gui_setup.py")))]
    for name, active, extra in chain:
        if active is not None:
            lines.append(python_event("SetActiveSource(FindSource(%r))" % active))
        lines.append(event(MENU, "activate", name))
        for port, source in extra.items():
            lines.append(event(DIALOG + "/buttonFrame/" + port, "activate"))
            lines.append(event(DIALOG + "/pipelineView", "currentChanged", TREE_ROWS[source]))
        if extra:
            lines.append(event(DIALOG + "/buttonBox/1QPushButton0", "activate"))  # OK
        lines.append(event(APPLY, "activate"))
    lines.append(python_event(run_file_code(os.path.join(HERE, "gui_check.py"))))
    lines.append("</pqevents>")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_print_part_events(path, model):
    steps = ["r = simple.OpenDataFile(%r, registrationName='model'); simple.Show(r); simple.SetActiveSource(r); "
             "simple.ResetCamera(); simple.Render()" % model]
    lines = ['<?xml version="1.0" ?>', "<pqevents>", python_event("from paraview import simple"),
             python_event(steps[0]), event(MENU, "activate", "GLPrintPart")]
    for name, value in PRINT_PART_PARAMETERS.items():  # typed into the panel before the one Apply
        lines.append(python_event("simple.FindSource('GLPrintPart1').SetPropertyWithName(%r, %r)" % (name, value)))
    lines += [event(APPLY, "activate"),
              # as a user clicks the render view (Apply made the new spreadsheet view active) and the toolpath
              python_event("simple.SetActiveView(simple.GetViews('RenderView')[0]); "
                           "simple.SetActiveSource(simple.FindSource('GLPrintPart1'))"),
              event(MENU, "activate", "GLToolpathReplay"), event(APPLY, "activate"),
              python_event(run_file_code(os.path.join(HERE, "gui_print_part_check.py"))),
              python_event("_gl_pp_first()"), python_event("_gl_pp_capture('gui_workbench_bunny.png')"),
              python_event("_gl_pp_maximize_summary()"), python_event("_gl_pp_capture('gui_summary_bunny.png')"),
              python_event("_gl_pp_maximize_summary(False)"),
              python_event("_gl_pp_second()"), "</pqevents>"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def run_cli_report(model, work):
    """report.json of the command line on the model with PRINT_PART_CLI, or (None, message)."""
    cli = os.environ.get("GEOLATTICE_CLI") or shutil.which("geolattice")
    if not cli:
        return None, "the command line (GEOLATTICE_CLI) was not found"
    out = os.path.join(work, "cli")
    start = time.time()
    done = subprocess.run([cli, "run", model, "-o", out] + PRINT_PART_CLI, capture_output=True, text=True,
                          timeout=600)
    print("geolattice run %s: %.1f s, exit code %d" % (" ".join(PRINT_PART_CLI), time.time() - start,
                                                      done.returncode), flush=True)
    report = os.path.join(out, "report.json")
    if not os.path.isfile(report):
        return None, "the command line wrote no report.json:\n" + done.stderr[-3000:]
    return report, None


def skip(message):
    print("SKIPPED: " + message, flush=True)
    return SKIP


NO_X_MESSAGES = ("Xvfb failed to start", "could not connect to display", "bad X server connection")


def run_paraview(command, env, timeout, log_path):
    """Runs the GUI under xvfb-run; returns (exit code or None if killed at the timeout, seconds, log,
    lines saying there was no display). A failure to get a display is retried once: `xvfb-run -a` picks
    the display number without a lock, so two runs starting together can collide."""
    for attempt in (1, 2):
        start = time.time()
        with open(log_path, "w") as log:
            proc = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, env=env, start_new_session=True)
            try:
                rc = proc.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                rc = None
            finally:
                # xvfb-run, Xvfb and paraview share the new session's process group: end them all.
                try:
                    os.killpg(proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                proc.wait()
        seconds = time.time() - start
        with open(log_path, errors="replace") as f:
            log_text = f.read()
        no_x = [l.strip() for l in log_text.splitlines() if any(m in l for m in NO_X_MESSAGES)]
        if rc is None or rc == 0 or not no_x or attempt == 2:
            return rc, seconds, log_text, no_x
        print("no display on attempt 1 (%s); retrying" % no_x[0][:200], flush=True)
        time.sleep(2)


def load_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--screenshot", default="geolattice_gui.png",
                        help="where to save the screenshot [./geolattice_gui.png]")
    parser.add_argument("--model", help="surface model [testdata/y_shape.obj]")
    parser.add_argument("--state", action="store_true",
                        help="instead: save a state with pvpython/geolattice_state.py (pvpython: $PVPYTHON or "
                             "PATH), start the GUI with --state=<it> and check what it shows")
    parser.add_argument("--print-part", action="store_true",
                        help="instead: one Apply of GL Print Part on the model [testdata/bunny.obj], its summary "
                             "against the command line's report.json, the replay played, three screenshots")
    parser.add_argument("--screenshot-dir", help="where --print-part saves its screenshots [the work directory]")
    parser.add_argument("--timeout", type=float, default=240.0, help="seconds before the GUI is killed [240]")
    parser.add_argument("--keep", action="store_true", help="keep the work directory (events, results, log)")
    args = parser.parse_args(argv)

    source_dir = os.environ.get("GEOLATTICE_SOURCE_DIR") or os.path.dirname(os.path.dirname(HERE))
    plugin = os.environ.get("GEOLATTICE_PLUGIN") or os.path.join(
        source_dir, "build", "lib", "paraview-5.11", "plugins", "GeoLattice", "GeoLattice.so")
    if not os.path.isfile(plugin):
        print("FAIL: GeoLattice plugin not found: %s (set GEOLATTICE_PLUGIN)" % plugin)
        return 1
    paraview = os.environ.get("PARAVIEW_EXECUTABLE") or shutil.which("paraview")
    if not paraview or not os.access(paraview, os.X_OK):
        return skip("the ParaView GUI executable (paraview) was not found; install Debian's paraview package")
    xvfb_run = os.environ.get("XVFB_RUN") or shutil.which("xvfb-run")
    if not xvfb_run or not shutil.which("Xvfb"):
        return skip("no X server can be made: %s not found on PATH (Debian package xvfb); the ParaView GUI "
                    "needs an X display (Debian's ParaView is built for GLX only)"
                    % ("xvfb-run" if not xvfb_run else "Xvfb"))
    if args.print_part and not shutil.which("xwd"):
        return skip("xwd (Debian package x11-apps) is not on the PATH: --print-part captures the GUI window with it")
    default_model = "bunny.obj" if args.print_part else "y_shape.obj"
    model = os.path.abspath(args.model or os.path.join(source_dir, "testdata", default_model))

    declared = plugin_filters(source_dir)
    failures = []
    for name, (group, category) in sorted(declared.items()):
        if group == "filters" and category != "GeoLattice":
            failures.append("%s: ShowInMenu category is %r, not 'GeoLattice'" % (name, category))
    menu_filters = {n for n, (g, _) in declared.items() if g == "filters"}
    chain = [step for step in CHAIN if step[0] in menu_filters]
    for name in sorted(menu_filters - {step[0] for step in chain}):
        failures.append("%s is a GeoLattice filter the GUI test does not cover: add it to CHAIN in %s"
                        % (name, os.path.abspath(__file__)))
    if failures and not (args.state or args.print_part):
        print("FAIL:\n  " + "\n  ".join(failures))
        return 1

    work = tempfile.mkdtemp(prefix="geolattice-gui-")
    screenshot = os.path.abspath(args.screenshot)
    if os.path.exists(screenshot):
        os.remove(screenshot)
    plan = {
        "model": model,
        "off_file": os.path.join(source_dir, "testdata", "decimated-knight.off"),
        "reader": READER_NAME,
        "chain": [[name, extra] for name, _, extra in chain],
        "filters": {name: category for name, (group, category) in declared.items() if group == "filters"},
        "readers": sorted(n for n, (g, _) in declared.items() if g == "sources"),
        "pvpython_dir": os.path.join(source_dir, "pvpython"),
        "none_arrays": none_array_properties(source_dir),
        "screenshot": screenshot,
        "setup_result": os.path.join(work, "setup.json"),
        "check_result": os.path.join(work, "check.json"),
    }
    plan_path = os.path.join(work, "plan.json")
    with open(plan_path, "w") as f:
        json.dump(plan, f, indent=1)
    events = os.path.join(work, "events.xml")
    extra_options = []
    if args.print_part:
        plan["report"], problem = run_cli_report(model, work)
        if problem:
            print("FAIL: " + problem)
            return 1
        plan["parameters"] = PRINT_PART_PARAMETERS
        plan["check_script"] = os.path.join(HERE, "gui_print_part_check.py")
        plan["screenshot_dir"] = os.path.abspath(args.screenshot_dir or work)
        os.makedirs(plan["screenshot_dir"], exist_ok=True)
        with open(plan_path, "w") as f:
            json.dump(plan, f, indent=1)
        write_print_part_events(events, model)
        stages = (("gui_print_part_check.py", "check_result"),)
    elif args.state:
        pvsm = os.path.join(work, "geolattice.pvsm")
        pvpython = os.environ.get("PVPYTHON") or shutil.which("pvpython")
        start = time.time()
        made = subprocess.run([pvpython, os.path.join(source_dir, "pvpython", "geolattice_state.py"), model,
                               "-o", pvsm, "--plugin", plugin], capture_output=True, text=True, timeout=300)
        print("geolattice_state.py: %.1f s, exit code %d" % (time.time() - start, made.returncode))
        if made.returncode != 0 or not os.path.isfile(pvsm):
            print("FAIL: geolattice_state.py could not save the state:\n" + made.stdout + made.stderr[-3000:])
            return 1
        extra_options = ["--state=" + pvsm]
        with open(events, "w") as f:
            f.write('<?xml version="1.0" ?>\n<pqevents>\n%s\n</pqevents>\n'
                    % python_event(run_file_code(os.path.join(HERE, "gui_state_check.py"))))
        stages = (("gui_state_check.py", "check_result"),)
    else:
        write_events(events, chain)
        stages = (("gui_setup.py", "setup_result"), ("gui_check.py", "check_result"))

    env = dict(os.environ, GEOLATTICE_GUI_PLAN=plan_path)
    env.pop("PV_PLUGIN_PATH", None)  # would auto-load whatever plugins it lists
    command = [xvfb_run, "-a", "-s", "-screen 0 1280x1024x24", paraview, "--dr",
               "--plugin-search-paths=" + os.path.dirname(os.path.abspath(plugin)), "--plugins=GeoLattice"]
    command += extra_options + ["--test-script=" + events, "--exit"]
    log_path = os.path.join(work, "paraview.log")
    print("running: " + " ".join(command), flush=True)
    rc, seconds, log_text, no_x = run_paraview(command, env, args.timeout, log_path)
    if rc is not None and rc != 0 and no_x:
        if not args.keep:
            shutil.rmtree(work, ignore_errors=True)
        return skip("no X server can be made: xvfb-run did not give paraview a display (%s; exit code %d)"
                    % (no_x[0][:200], rc))

    problems = []
    if rc is None:
        problems.append("the GUI did not finish within %g s (killed)" % args.timeout)
    elif rc != 0:
        problems.append("paraview exited with %d (event playback failed or a crash; see the log lines below)" % rc)
    check = None
    for stage, key in stages:
        result = load_json(plan[key])
        if result is None:
            problems.append("%s wrote no result (it did not run or crashed)" % stage)
        else:
            problems += ["%s: %s" % (stage, m) for m in result.get("failures", [])]
            check = result
    if check:
        for name, info in check.get("outputs", {}).items():
            print("  %-26s %s" % (name, info))
    if not problems and not args.print_part and not os.path.isfile(screenshot):
        problems.append("no screenshot at %s" % screenshot)
    print("GUI run: %.1f s (paraview exit code %s)" % (seconds, rc))
    if problems:
        print("FAIL:\n  " + "\n  ".join(problems))
        interesting = [l for l in log_text.splitlines()
                       if re.search(r"critical|error|Couldn't|Traceback|signal", l, re.I) and "Available widget" not in l]
        print("paraview log (%s), error lines:\n  %s" % (log_path, "\n  ".join(interesting[:40]) or "(none)"))
        print("work directory kept: %s" % work)
        return 1
    if args.print_part:
        print("PASS: GL Print Part with one Apply on %s: the summary is report.json's, the replay plays; "
              "screenshots in %s" % (os.path.basename(model), plan["screenshot_dir"]))
    elif args.state:
        print("PASS: the state saved by geolattice_state.py loads in the GUI; screenshot %s" % screenshot)
    else:
        print("PASS: %d GeoLattice filters created from Filters > GeoLattice and applied; screenshot %s"
              % (len(chain), screenshot))
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    else:
        print("work directory: %s" % work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
