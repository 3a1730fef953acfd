# The house style of the lectures' figures (scripts/figures.sh loads it first), as in
# bench/plot_precision.gp: cairo's PNG terminal, DejaVu Sans, light grid, one colour per series.
# Each figure script then sets its own size with `set terminal pngcairo size W,H`.
set encoding utf8
set terminal pngcairo size 800,450 enhanced font 'DejaVu Sans,10' linewidth 1.5
set grid xtics ytics lc rgb '#dddddd'
red = '#d62728'; blue = '#1f77b4'; green = '#2ca02c'; orange = '#ff7f0e'; grey = '#7f7f7f'; purple = '#9467bd'
