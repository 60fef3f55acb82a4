# map.gp: a map that pneumachaos wrote (stability --map CSV, a sweep's points.csv) as a PNG the
# guide shows: one square per grid point, coloured by a column.
#   gnuplot -c map.gp DATA.csv OUT.png XCOL YCOL ZCOL ZMIN ZMAX 'X label' 'Y label'
# Columns are numbers (1 = the first); the header names the axes. The colour scale runs from
# ZMIN (blue) through the middle (white) to ZMAX (red), so a scale symmetric about 0 shows a sign.
set datafile separator ','
set terminal pngcairo size 820,380 font 'Sans,10'
set output ARG2
set grid
set palette defined (0 'blue', 1 'white', 2 'red')
set cbrange [real(ARG6):real(ARG7)]
set key off
set xlabel ARG8 noenhanced
set ylabel ARG9 noenhanced
plot ARG1 using int(ARG3):int(ARG4):int(ARG5) with points pt 5 ps 1.4 palette
