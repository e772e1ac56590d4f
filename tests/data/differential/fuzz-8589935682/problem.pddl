(define (problem fuzz-8589935682-1) (:domain fuzz-8589935682)
  (:init (f1))
  (:goal (and (f4)))
  (:metric minimize (total-time)))
