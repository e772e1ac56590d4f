(define (problem fuzz-4294971080-1) (:domain fuzz-4294971080)
  (:init (f0) (f3))
  (:goal (and (f2)))
  (:metric minimize (total-time)))
