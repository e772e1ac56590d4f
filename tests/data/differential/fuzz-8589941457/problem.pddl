(define (problem fuzz-8589941457-1) (:domain fuzz-8589941457)
  (:init)
  (:goal (and (f1)))
  (:metric minimize (total-time)))
