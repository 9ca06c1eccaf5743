# The picture of rail_wear_hunting's output (run in its OUT_DIR):
#   gnuplot rail_wear_hunting.gp   ->  rail_wear_hunting.png
# Top: the rail head (y towards the field side, z down, so drawn with z
# reversed) with the contact points of every step's hunting cycle, coloured
# by the wheelset's lateral shift. Bottom: the depth worn vertically over 10^4 axle
# passages against y.
set terminal pngcairo size 900,760 font "sans,11"
set output "rail_wear_hunting.png"
set datafile separator ","
set key autotitle columnhead
set multiplot layout 2,1 title "UIC60 rail worn by a hunting S1002 wheelset: 10^4 axle passages"
set lmargin 12
set xrange [-42:28]
set ylabel "z [mm] (down)"
set yrange [14:-2]
set cbrange [-5:5]
set cblabel "wheelset shift y_{ws} [mm]"
set palette defined (-5 "#2166ac", 0 "#f7f7f7", 5 "#b2182b")
set key bottom right
plot "rail_wear_hunting.csv" using 1:2 with lines lw 2 lc rgb "black" title "rail head (initial)", \
     "rail_wear_contacts.csv" using 6:7:3 with points pt 7 ps 1.4 palette title "contact points"
unset cbrange
unset cblabel
set xlabel "y on the rail profile [mm] (gauge side left, field side right)"
set ylabel "vertical wear depth [um]"
set yrange [0:*]
set key top right
plot "rail_wear_hunting.csv" using 1:4 with lines lw 2 lc rgb "#b2182b" title "worn depth after 10^4 passages"
unset multiplot
