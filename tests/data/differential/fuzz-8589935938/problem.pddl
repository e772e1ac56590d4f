(define (problem fuzz-8589935938-1) (:domain fuzz-8589935938)
  (:init (= (x0) 2) (f1))
  (:goal (and (f3) (>= (x0) 2)))
  (:metric minimize (total-time)))
