(define (problem fuzz-8589940174-1) (:domain fuzz-8589940174)
  (:init (= (x0) 2) (= (x1) 2))
  (:goal (and (f1)))
  (:metric minimize (total-time)))
