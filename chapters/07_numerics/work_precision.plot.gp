# A panel's curves (@curves@: work_precision.method.gp, one per method of its family; then
# @comparison@: rk8pd in grey, work_precision.rk8pd.gp, where it is not one of them), the
# double-precision floor and the target.
plot @curves@@comparison@, @floor@ with lines lc rgb '#777777' dt 2 lw 1.2 title 'double-precision floor', @target@ with lines lc rgb '#aaaaaa' dt 3 lw 1.2 title 'target @target_text@'
