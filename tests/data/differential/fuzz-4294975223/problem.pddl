(define (problem fuzz-4294975223-1) (:domain fuzz-4294975223)
  (:init (= (x0) 1) (f0))
  (:goal (and (f3)))
  (:metric minimize (total-time)))
