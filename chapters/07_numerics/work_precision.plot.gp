# A panel's curves (the scene's, each followed by ", "), the double-precision floor and the
# target.
plot @curves@@floor@ with lines lc rgb '#777777' dt 2 lw 1.2 title 'double-precision floor', @target@ with lines lc rgb '#aaaaaa' dt 3 lw 1.2 title 'target @target_text@'
