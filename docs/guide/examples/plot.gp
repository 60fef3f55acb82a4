# plot.gp: one or two columns of a CSV that pneumachaos wrote, as a PNG the guide shows.
#   gnuplot -c plot.gp DATA.csv OUT.png XCOL YCOL [YCOL2] [points]
# Columns are numbers (1 = the first); the header line names the curves and the axes. With a
# second y column it goes on the right-hand axis; "points" draws dots instead of lines.
set datafile separator ','
set terminal pngcairo size 820,340 font 'Sans,10' noenhanced
set output ARG2
set key autotitle columnhead below horizontal
set grid
style = (ARGC >= 6 && ARG6 eq "points") ? "points pt 7 ps 0.4" : "lines"
x = int(ARG3)
y = int(ARG4)
if (ARGC >= 5 && ARG5 ne "") {
  y2 = int(ARG5)
  set y2tics
  plot ARG1 using x:y with @style, '' using x:y2 with @style axes x1y2
} else {
  plot ARG1 using x:y with @style
}
