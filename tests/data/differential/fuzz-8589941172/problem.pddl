(define (problem fuzz-8589941172-1) (:domain fuzz-8589941172)
  (:init (= (x0) 0) (f1))
  (:goal (and (f0)))
  (:metric minimize (total-time)))
