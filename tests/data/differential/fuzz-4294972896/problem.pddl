(define (problem fuzz-4294972896-1) (:domain fuzz-4294972896)
  (:init (at 1.25 (f0)) (f3) (at 1.5 (not (f3))) (f3))
  (:goal (and (f1)))
  (:metric minimize (total-time)))
