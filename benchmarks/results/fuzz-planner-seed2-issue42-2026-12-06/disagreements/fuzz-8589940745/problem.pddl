(define (problem fuzz-8589940745-1) (:domain fuzz-8589940745)
  (:init (= (x0) 2) (f1))
  (:goal (and (f2)))
  (:metric minimize (total-time)))
