# Chapter 9's size table as a figure (bench/parallel_figure.sh): two ranks on this machine.
set terminal pngcairo size 900,1000 font 'sans,11'
set output 'scaling.png'
reset
set multiplot layout 2,1
set logscale xy
set format x '10^{%L}'
set grid
set xrange [5e4:3e7]
set key bottom right
set xlabel 'unknowns'
set ylabel 'wall time [s]'
set title 'The whole contact solve against one factorization of K'
plot 'scaling.dat' index 0 using 1:2 with linespoints pt 7 lw 2 title 'whole contact solve, nested levels, CG + GAMG (2 ranks)', \
     'scaling.dat' index 0 using 1:3 with linespoints pt 4 lw 2 dt 2 title 'physical limit: assemble, factorize (CHOLMOD) and solve K once', \
     [1e5:2e7] 2e-6 * x title 'slope 1 (O(n))' dt 3 lc rgb 'black'
unset logscale y
set yrange [0:3000]
set ylabel 'peak memory [bytes per unknown]'
set title 'Peak resident memory per unknown'
set key top right
plot 'scaling.dat' index 0 using 1:4 with linespoints pt 7 lw 2 title 'contact solve, CG + GAMG (all ranks)', \
     'scaling.dat' index 0 using 1:5 with linespoints pt 4 lw 2 dt 2 title 'CHOLMOD (rank 0, through the limit)'
unset multiplot
set terminal pdfcairo size 6.25,6.94 font 'sans,8'
set output 'scaling.pdf'
reset
set multiplot layout 2,1
set logscale xy
set format x '10^{%L}'
set grid
set xrange [5e4:3e7]
set key bottom right
set xlabel 'unknowns'
set ylabel 'wall time [s]'
set title 'The whole contact solve against one factorization of K'
plot 'scaling.dat' index 0 using 1:2 with linespoints pt 7 lw 2 title 'whole contact solve, nested levels, CG + GAMG (2 ranks)', \
     'scaling.dat' index 0 using 1:3 with linespoints pt 4 lw 2 dt 2 title 'physical limit: assemble, factorize (CHOLMOD) and solve K once', \
     [1e5:2e7] 2e-6 * x title 'slope 1 (O(n))' dt 3 lc rgb 'black'
unset logscale y
set yrange [0:3000]
set ylabel 'peak memory [bytes per unknown]'
set title 'Peak resident memory per unknown'
set key top right
plot 'scaling.dat' index 0 using 1:4 with linespoints pt 7 lw 2 title 'contact solve, CG + GAMG (all ranks)', \
     'scaling.dat' index 0 using 1:5 with linespoints pt 4 lw 2 dt 2 title 'CHOLMOD (rank 0, through the limit)'
unset multiplot
