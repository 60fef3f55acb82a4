# plot.gp: one or two columns of a CSV that pneumachaos wrote, as a PNG the guide shows.
#   gnuplot -c plot.gp DATA.csv OUT.png XCOL YCOL [YCOL2] [OPTIONS] [XFROM:XTO]
# Columns are numbers (1 = the first); the header line names the curves. OPTIONS: "y2" puts the
# second column on the right-hand axis (another unit), "points" draws dots instead of lines
# (both: "y2,points"); XFROM:XTO limits the x axis. The axes are labelled with the columns'
# headers, which carry their units (t[s], v[m/s]).
set datafile separator ','
set terminal pngcairo size 820,340 font 'Sans,10' noenhanced
set output ARG2
set key autotitle columnhead below horizontal
set grid
options = (ARGC >= 6) ? ARG6 : ""
style = strstrt(options, "points") ? "points pt 7 ps 0.4" : "lines"
axes2 = strstrt(options, "y2") ? "x1y2" : "x1y1"
if (ARGC >= 7 && ARG7 ne "") { eval "set xrange [" . ARG7 . "]" }
x = int(ARG3)
y = int(ARG4)
header = system(sprintf("head -n 1 '%s' | tr ',' ' '", ARG1))
set xlabel word(header, x)
set ylabel word(header, y)
if (ARGC >= 5 && ARG5 ne "") {
  y2 = int(ARG5)
  if (axes2 eq "x1y2") { set y2tics; set y2label word(header, y2) }
  plot ARG1 using x:y with @style, '' using x:y2 with @style axes @axes2
} else {
  plot ARG1 using x:y with @style
}
