#!/usr/bin/python3
"""Check a G-code file with LinuxCNC's own RS274NGC interpreter, with the axis
letters of a machine INI.

The standalone 'rs274' program of LinuxCNC 2.9 only knows the axes X Y Z A B C
(its axis mask is hard-coded), so it rejects the extruder axis U with
"Bad character 'u' used" whatever INI is given.  This script runs the same
interpreter through the 'gcode' Python module that the AXIS preview uses
(package linuxcnc-uspace), with the axis mask taken from [TRAJ]COORDINATES of
the INI, so it accepts exactly the letters the configured machine accepts.

usage:  /usr/bin/python3 geolattice-gcode-check.py MACHINE.ini FILE.ngc [-q]
prints one line per move (XYZ/U in mm, ABC in degrees, feed in units/min as
the interpreter computed it from G93 inverse time) unless -q; exit status 1
and a message on stderr on the first interpreter error.
It checks syntax and interpreter rules only: no axis/joint limits, no
kinematics, no velocity limits (those are checked by LinuxCNC's task/motion).
"""
import atexit, configparser, os, shutil, sys, tempfile
import gcode  # from linuxcnc-uspace (/usr/lib/python3/dist-packages)

if len(sys.argv) < 3:
    sys.exit(__doc__)
ini, ngc = sys.argv[1], sys.argv[2]
quiet = "-q" in sys.argv[3:]
os.environ["INI_FILE_NAME"] = os.path.abspath(ini)  # interpreter reads [RS274NGC] etc.

cp = configparser.ConfigParser(strict=False, interpolation=None)
cp.optionxform = str
cp.read(ini)
coords = cp.get("TRAJ", "COORDINATES").replace(" ", "").upper()
MASK = sum(1 << "XYZABCUVW".index(ch) for ch in set(coords))
LETTERS = "XYZABCUVW"
LINEAR = (0, 1, 2, 6, 7, 8)
MM = 25.4  # the gcode module reports lengths in inches


TMP = tempfile.mkdtemp(prefix="glcheck")  # scratch parameter (.var) file
atexit.register(shutil.rmtree, TMP, True)
open(os.path.join(TMP, "check.var"), "w").close()


class Canon:
    parameter_file = os.path.join(TMP, "check.var")

    def __init__(self):
        self.out = []

    # queries from the interpreter
    def get_axis_mask(self): return MASK
    def get_block_delete(self): return False
    def get_external_angular_units(self): return 1.0
    def get_external_length_units(self): return 1.0 / MM  # machine units: mm
    def get_tool(self, pocket): return (-1,) + (0.0,) * 12 + (0,)
    def check_abort(self): return False

    # canonical calls that are reported
    def _pos(self, args):
        return " ".join("%s%.4f" % (LETTERS[i], v * MM if i in LINEAR else v)
                        for i, v in enumerate(args[:9]) if MASK & (1 << i))
    def straight_feed(self, *a): self.out.append("FEED     " + self._pos(a))
    def straight_traverse(self, *a): self.out.append("TRAVERSE " + self._pos(a))
    def set_feed_rate(self, f): self.out.append("FEEDRATE %.4f" % (f * MM))
    def comment(self, s): self.out.append("COMMENT  " + s)
    def message(self, s): self.out.append("MESSAGE  " + s)

    def __getattr__(self, name):  # every other canonical call: ignored
        if name.startswith("__"):
            raise AttributeError(name)
        return lambda *a, **k: None


canon = Canon()
result, seq = gcode.parse(ngc, canon)
if not quiet:
    print("\n".join(canon.out))
if result > gcode.MIN_ERROR:
    print("%s: error near line %d: %s" % (ngc, seq, gcode.strerror(result)), file=sys.stderr)
    sys.exit(1)
