(define (problem fuzz-8589948526-1) (:domain fuzz-8589948526)
  (:init (f3))
  (:goal (and (f1) (preference pg (f1))))
  (:metric minimize (+ (total-time) (* 3 (is-violated pg)) (* 2 (is-violated pp)))))
