(define (problem fuzz-4294971720-1) (:domain fuzz-4294971720)
  (:init (at 2.5 (f2)) (at 3.5 (not (f2))) (f4) (at 1 (not (f4))) (= (x0) 1) (f4) (g0 o2))
  (:goal (and (f2)))
  (:metric minimize (total-time)))
