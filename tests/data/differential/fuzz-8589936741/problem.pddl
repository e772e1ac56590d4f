(define (problem fuzz-8589936741-1) (:domain fuzz-8589936741)
  (:init (f4))
  (:goal (and (f2)))
  (:metric minimize (total-time)))
