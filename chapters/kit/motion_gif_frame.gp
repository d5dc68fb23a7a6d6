set label 1 't = @t@' at screen 0.03, 0.94
splot @curves@
