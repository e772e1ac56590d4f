(define (problem fuzz-4294972041-1) (:domain fuzz-4294972041)
  (:init)
  (:goal (and (f0)))
  (:metric minimize (total-time)))
