(define (problem fuzz-4294974730-1) (:domain fuzz-4294974730)
  (:init (at 1.5 (f0)) (at 1.5 (f0)) (at 3.5 (not (f0))) (g0 o1) (g0 o2))
  (:goal (and (f2)))
  (:metric minimize (total-time)))
