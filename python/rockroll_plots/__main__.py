"""python3 -m rockroll_plots validate DIR | output DIR PLOTS_DIR   (exit 2: bad input)"""
import sys


def main(argv):
    usage = "usage: python3 -m rockroll_plots validate DIR | output DIR PLOTS_DIR"
    if len(argv) < 2 or (argv[0], len(argv)) not in (("validate", 2), ("output", 3)):
        print(usage, file=sys.stderr)
        return 2
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print(f"rockroll plot: matplotlib is missing for {sys.executable}: apt-get install python3-matplotlib "
              "(or set ROCKROLL_PYTHON to a Python that has it)", file=sys.stderr)
        return 2
    from .figures import BadInput
    try:
        if argv[0] == "validate":
            from .validate import plot_validation
            plot_validation(argv[1])
        else:
            from .outputs import plot_output
            kind = plot_output(argv[1], argv[2])
            print(f"plotted the {kind} output {argv[1]}")
    except BadInput as e:
        print(f"rockroll plot: bad input: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
