# map.gp: a map that pneumachaos wrote (stability --map CSV, a sweep's points.csv) as a PNG the
# guide shows: one square per grid point, coloured by a column.
#   gnuplot -c map.gp DATA.csv OUT.png XCOL YCOL ZCOL ZMIN ZMAX 'X label' 'Y label'
# Columns are numbers (1 = the first). The colour scale runs from ZMIN (blue) through the middle
# (white) to ZMAX (red), so a scale symmetric about 0 shows a sign; the colour bar is labelled
# with ZCOL's header, its underscores as spaces (gnuplot passes a script at most 9 arguments).
# Each square has a grey outline, so a point coloured the middle of the scale (white) is seen
# on the white page.
set datafile separator ','
set terminal pngcairo size 820,380 font 'Sans,10'
set output ARG2
set grid
set palette defined (0 'blue', 1 'white', 2 'red')
set cbrange [real(ARG6):real(ARG7)]
set key off
set xlabel ARG8 noenhanced
set ylabel ARG9 noenhanced
header = system(sprintf("head -n 1 '%s' | tr ',' ' '", ARG1))
set cblabel system(sprintf("echo '%s' | tr '_' ' '", word(header, int(ARG5)))) noenhanced
plot ARG1 using int(ARG3):int(ARG4):int(ARG5) with points pt 5 ps 1.4 palette, \
     '' using int(ARG3):int(ARG4) with points pt 4 ps 1.4 lc rgb 'gray50'
