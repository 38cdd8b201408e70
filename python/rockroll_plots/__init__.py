"""rockroll's plots (matplotlib, Debian's python3-matplotlib under /usr/bin/python3).

One module draws every plot rockroll makes: `rockroll validate`'s report figures
(validate.py) and `rockroll plot DIR` for a run, sweep, steady, modes or study output
directory (outputs.py). Both read the CSV files by column name and draw through
figures.plot_csv, which records every line in a sidecar NAME.png.json (figures.save):
the CSV file, the rows used, the x and y columns with their scales, the number of
points and a few drawn values taken back from matplotlib. The tests compare the
sidecars with the CSV columns, so a plot drawing the wrong column fails a test.

Run as `python3 -m rockroll_plots validate DIR` or
`python3 -m rockroll_plots output DIR PLOTS_DIR` (the rockroll program does this,
with this package's parent folder on PYTHONPATH). Exit 2 for bad input."""
