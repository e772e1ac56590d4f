(define (problem fuzz-4294972298-1) (:domain fuzz-4294972298)
  (:init (= (x0) 0))
  (:goal (and (f3)))
  (:metric minimize (total-time)))
