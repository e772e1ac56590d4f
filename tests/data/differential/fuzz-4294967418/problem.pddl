(define (problem fuzz-4294967418-1) (:domain fuzz-4294967418)
  (:init (at 2.5 (f3)) (at 4 (not (f3))) (at 1.25 (f4)) (at 5.75 (not (f4))) (= (x0) 0) (g0 o2))
  (:goal (and (f0) (>= (x0) 3)))
  (:metric minimize (total-time)))
